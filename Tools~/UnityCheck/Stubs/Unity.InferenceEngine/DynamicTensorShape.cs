namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/ShapeInference/DynamicTensorShape.cs
    public partial struct DynamicTensorShape
    {
        public int[] ToIntArray() => throw null!;
    }
}
