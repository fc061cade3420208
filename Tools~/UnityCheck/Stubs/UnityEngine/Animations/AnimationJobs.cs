using UnityEngine.Playables;

namespace UnityEngine.Animations
{
    // source: unity:Modules/Animation/Managed/IAnimationJob.cs
    public partial interface IAnimationJob
    {
        void ProcessAnimation(AnimationStream stream);

        void ProcessRootMotion(AnimationStream stream);
    }

    // source: unity:Modules/Animation/Managed/IAnimationJobPlayable.cs
    public partial interface IAnimationJobPlayable : IPlayable
    {
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationStream.bindings.cs
    public partial struct AnimationStream
    {
        public float deltaTime => throw null!;

        public Vector3 velocity { get => throw null!; set => throw null!; }

        public Vector3 angularVelocity { get => throw null!; set => throw null!; }

        public bool isValid => throw null!;

        public int inputStreamCount => throw null!;

        public AnimationStream GetInputStream(int index) => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationStreamHandles.bindings.cs
    public partial struct TransformStreamHandle
    {
        public Vector3 GetLocalPosition(AnimationStream stream) => throw null!;

        public void SetLocalPosition(AnimationStream stream, Vector3 position) => throw null!;

        public Quaternion GetLocalRotation(AnimationStream stream) => throw null!;

        public void SetLocalRotation(AnimationStream stream, Quaternion rotation) => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimatorJobExtensions.bindings.cs
    public static partial class AnimatorJobExtensions
    {
        public static TransformStreamHandle BindStreamTransform(this Animator animator, Transform transform) => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationScriptPlayable.bindings.cs
    public partial struct AnimationScriptPlayable : IAnimationJobPlayable
    {
        public static AnimationScriptPlayable Create<T>(PlayableGraph graph, T jobData, int inputCount = 0)
            where T : struct, IAnimationJob => throw null!;

        public void SetProcessInputs(bool value) => throw null!;

        public static implicit operator Playable(AnimationScriptPlayable playable) => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationClipPlayable.bindings.cs
    public partial struct AnimationClipPlayable : IPlayable
    {
        public static AnimationClipPlayable Create(PlayableGraph graph, AnimationClip clip) => throw null!;

        public void SetApplyFootIK(bool value) => throw null!;

        public void SetApplyPlayableIK(bool value) => throw null!;

        public AnimationClip GetAnimationClip() => throw null!;

        public static implicit operator Playable(AnimationClipPlayable playable) => throw null!;

        public static explicit operator AnimationClipPlayable(Playable playable) => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationPlayableOutput.bindings.cs
    public partial struct AnimationPlayableOutput : IPlayableOutput
    {
        public static AnimationPlayableOutput Create(PlayableGraph graph, string name, Animator target) => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationMixerPlayable.bindings.cs
    public partial struct AnimationMixerPlayable : IPlayable
    {
        public static AnimationMixerPlayable Create(PlayableGraph graph, int inputCount = 0) => throw null!;

        public static implicit operator Playable(AnimationMixerPlayable playable) => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimationLayerMixerPlayable.bindings.cs
    public partial struct AnimationLayerMixerPlayable : IPlayable
    {
        public static AnimationLayerMixerPlayable Create(PlayableGraph graph, int inputCount = 0) => throw null!;

        public static implicit operator Playable(AnimationLayerMixerPlayable playable) => throw null!;
    }

    // source: unity:Modules/Animation/Managed/AnimationPlayableBinding.cs
    public static partial class AnimationPlayableBinding
    {
        public static PlayableBinding Create(string name, Object key) => throw null!;
    }
}
