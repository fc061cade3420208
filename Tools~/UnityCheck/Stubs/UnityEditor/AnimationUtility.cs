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
    }
}
