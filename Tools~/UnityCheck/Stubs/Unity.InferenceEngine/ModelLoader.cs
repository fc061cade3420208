namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/Serialization/ModelLoader.cs
    public static partial class ModelLoader
    {
        public static Model Load(ModelAsset modelAsset) => throw null!;
    }
}
