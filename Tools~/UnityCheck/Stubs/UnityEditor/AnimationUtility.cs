using UnityEngine;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Animation/AnimationUtility.bindings.cs
    public partial class AnimationUtility
    {
        public static EditorCurveBinding[] GetCurveBindings(AnimationClip clip) => throw null!;

        public static AnimationCurve GetEditorCurve(AnimationClip clip, EditorCurveBinding binding) => throw null!;

        public static void SetEditorCurve(AnimationClip clip, EditorCurveBinding binding, AnimationCurve curve) => throw null!;

        public static string CalculateTransformPath(Transform targetTransform, Transform root) => throw null!;

        public static AnimationClipSettings GetAnimationClipSettings(AnimationClip clip) => throw null!;

        public static void SetAnimationClipSettings(AnimationClip clip, AnimationClipSettings srcClipInfo) => throw null!;
    }

    // source: unity:Editor/Mono/Animation/AnimationClipSettings.bindings.cs
    public partial class AnimationClipSettings
    {
        public bool loopTime;
        public bool loopBlend;
    }
}
