using UnityEngine;

namespace UnityEditor.Animations
{
    // source: unity:Editor/Mono/Animation/AnimatorController.cs
    public sealed partial class AnimatorController : RuntimeAnimatorController
    {
        public static AnimatorController CreateAnimatorControllerAtPathWithClip(string path, AnimationClip clip) => throw null!;
    }
}
