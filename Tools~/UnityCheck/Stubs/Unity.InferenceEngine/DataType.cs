namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/Backends/CPU/NativeTensorArray.cs
    public enum DataType
    {
        Float,
        Int,
        Short,
        Byte,
        Custom
    }
}
