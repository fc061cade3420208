using UnityEngine.Animations;

namespace UnityEngine.Experimental.Animations
{
    // source: unity:Modules/Animation/ScriptBindings/AnimationPlayableOutputExtensions.bindings.cs
    public enum AnimationStreamSource
    {
        DefaultValues,
        PreviousInputs,
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationPlayableOutputExtensions.bindings.cs
    public static partial class AnimationPlayableOutputExtensions
    {
        public static void SetAnimationStreamSource(this AnimationPlayableOutput output, AnimationStreamSource streamSource) => throw null!;

        public static ushort GetSortingOrder(this AnimationPlayableOutput output) => throw null!;

        public static void SetSortingOrder(this AnimationPlayableOutput output, ushort sortingOrder) => throw null!;
    }
}
