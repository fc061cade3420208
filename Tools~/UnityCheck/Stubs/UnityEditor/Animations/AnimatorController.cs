using UnityEngine;

namespace UnityEditor.Animations
{
    // source: unity:Editor/Mono/Animation/AnimatorController.cs
    public sealed partial class AnimatorController : RuntimeAnimatorController
    {
        public static AnimatorController CreateAnimatorControllerAtPathWithClip(string path, AnimationClip clip) => throw null!;

        // source: unity:Editor/Mono/AnimatorController.bindings.cs
        public AnimatorControllerLayer[] layers { get => throw null!; set => throw null!; }
    }

    // source: unity:Editor/Mono/AnimatorControllerLayer.bindings.cs
    public partial class AnimatorControllerLayer
    {
        public bool iKPass { get => throw null!; set => throw null!; }
    }
}
