using UnityEngine;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Animation/AnimationWindow/AnimationWindow.cs
    public sealed partial class AnimationWindow : EditorWindow
    {
        public AnimationClip animationClip { get => throw null!; set => throw null!; }

        public bool previewing { get => throw null!; set => throw null!; }
    }
}
