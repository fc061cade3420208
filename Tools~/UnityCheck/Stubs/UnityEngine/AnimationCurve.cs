namespace UnityEngine
{
    // source: unity:Runtime/Export/Animation/AnimationCurve.bindings.cs
    public partial class AnimationCurve
    {
        public AnimationCurve(params Keyframe[] keys) => throw null!;

        public Keyframe[] keys { get => throw null!; set => throw null!; }

        // UnityCsReference 6000.0 Runtime/Export/Animation/AnimationCurve.bindings.cs:171-173 (extern, thread-safe)
        public float Evaluate(float time) => throw null!;
    }
}
