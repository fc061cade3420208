using UnityEngine;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Animation/AnimationUtility.bindings.cs
    public partial class AnimationUtility
    {
        public enum TangentMode
        {
            Free = 0,
            Auto = 1,
            Linear = 2,
            Constant = 3,
            ClampedAuto = 4
        }

        public static void SetEditorCurves(AnimationClip clip, EditorCurveBinding[] bindings, AnimationCurve[] curves) => throw null!;

        public static TangentMode GetKeyLeftTangentMode(AnimationCurve curve, int index) => throw null!;

        public static TangentMode GetKeyRightTangentMode(AnimationCurve curve, int index) => throw null!;

        public static bool GetKeyBroken(AnimationCurve curve, int index) => throw null!;

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
