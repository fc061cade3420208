namespace UnityEngine
{
    // source: unity:Runtime/Export/Animation/AnimationCurve.bindings.cs
    public partial struct Keyframe
    {
        public Keyframe(float time, float value, float inTangent, float outTangent) => throw null!;

        public float time { get => throw null!; set => throw null!; }
    }
}
