namespace UnityEngine
{
    // source: unity:Runtime/Export/Animation/AnimationCurve.bindings.cs
    public partial class AnimationCurve
    {
        public AnimationCurve(params Keyframe[] keys) => throw null!;

        public Keyframe[] keys { get => throw null!; set => throw null!; }
    }
}
