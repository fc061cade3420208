namespace UnityEngine
{
    // source: unity:Runtime/Export/Animation/AnimationCurve.bindings.cs
    public partial struct Keyframe
    {
        public Keyframe(float time, float value, float inTangent, float outTangent) => throw null!;

        public float time { get => throw null!; set => throw null!; }

        public float value { get => throw null!; set => throw null!; }

        public float inTangent { get => throw null!; set => throw null!; }

        public float outTangent { get => throw null!; set => throw null!; }

        public float inWeight { get => throw null!; set => throw null!; }

        public float outWeight { get => throw null!; set => throw null!; }

        public WeightedMode weightedMode { get => throw null!; set => throw null!; }
    }
}
