using UnityEngine;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Animation/AnimationMode.bindings.cs
    public partial class AnimationMode
    {
        public static void StopAnimationMode() => throw null!;

        public static bool InAnimationMode() => throw null!;

        public static void StartAnimationMode() => throw null!;

        public static void BeginSampling() => throw null!;

        public static void EndSampling() => throw null!;

        public static void SampleAnimationClip(GameObject gameObject, AnimationClip clip, float time) => throw null!;
    }
}
