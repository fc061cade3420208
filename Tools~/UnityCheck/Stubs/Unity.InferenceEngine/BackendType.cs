namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/InferenceEngine.cs
    public enum DeviceType
    {
        GPU = 1 << 8,
        CPU = 1 << 9,
    }

    // source: inference:Runtime/Core/InferenceEngine.cs
    public enum BackendType
    {
        GPUCompute = 0 | DeviceType.GPU,
        GPUPixel = 1 | DeviceType.GPU,
        CPU = 0 | DeviceType.CPU,
    }
}
