using System;
using DeltaInterpolator.Core.Playback;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Experimental.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Binds a character's frame to its animation job, the way Animation Rigging binds constraint data to its jobs:
    /// it owns the job's buffers and the playable graph, creates the <see cref="TransitionLayerJob"/> over them as a
    /// layer after the Animator Controller (and, just before it, the readers of clip and Animator state targets), carries out
    /// each <see cref="CharacterFrameOutput"/> (the pose into the job, a state to sample, a hand-off's state for the Animator to
    /// play), and hands back what was read (the pose shown, the controller's root velocity, a sampled target, the watched
    /// layers' state machines). Pose buffers hold the root position (3 values) then bones × 4 rotation values (w, x, y, z).
    /// </summary>
    internal sealed class TransitionLayerBinder : IDisposable
    {
        private readonly PoseBlendBuffers _buffers;
        // [0..2] the transition's root velocity (main thread → job), [3..5] the controller's (job → main thread), [6] 1 with root motion on.
        private NativeArray<double> _rootVelocity;
        // One flag per bone: true where a masked controller layer above drives the bone (it keeps the controller's pose); empty: no mask.
        private NativeArray<bool> _keptBones;
        private PlayableGraph _graph;
        private readonly Animator _animator;
        private readonly AnimatorTransitionWatcher _watcher;
        private bool _stateTargetLatest;
        // A hand-off's state the Animator was told to play last frame, to check at the next frame that it did.
        private bool _playPending;
        private int _playedState;
        private int _playedLayer;
        private bool _warnedPlay;

        /// <summary>
        /// Binds <paramref name="bones"/> of <paramref name="animator"/> (the root bone first) in a graph named
        /// <paramref name="graphName"/> whose output sorts at <paramref name="sortingOrder"/>; until the job first runs, the
        /// pose shown is the bones' pose now.
        /// </summary>
        public TransitionLayerBinder(Animator animator, Transform[] bones, string graphName, ushort sortingOrder, AnimatorTransitionWatcher watcher)
        {
            _animator = animator;
            _watcher = watcher;
            const int rootBone = 0;
            double[] initialPose = UnityPoses.Read(bones, rootBone);
            _buffers = new PoseBlendBuffers(animator, bones);
            _rootVelocity = new NativeArray<double>(7, Allocator.Persistent);
            bool[]? kept = watcher.KeptBones;
            _keptBones = new NativeArray<bool>(kept?.Length ?? 0, Allocator.Persistent);
            for (int b = 0; kept != null && b < kept.Length; b++) _keptBones[b] = kept[b];
            // Until the job has run once (it does not while the Animator is culled), the pose shown is the bones' own, never zeros.
            initialPose.CopyTo(_buffers.Shown.AsSpan());
            var job = new TransitionLayerJob { Bones = _buffers.Bones, Pose = _buffers.Pose, Shown = _buffers.Shown, Weight = _buffers.Weight, RootVelocity = _rootVelocity, KeptBones = _keptBones, RootBone = rootBone };
            _graph = PlayableGraph.Create(graphName);
            _graph.SetTimeUpdateMode(DirectorUpdateMode.GameTime);
            AnimationPlayableOutput output = AnimationPlayableOutput.Create(_graph, "Δ-Interpolator", animator);
            AnimationScriptPlayable playable = AnimationScriptPlayable.Create(_graph, job);
            output.SetSourcePlayable(playable);
            // Read what the Animator Controller produced (the outputs before this one), then blend over it.
            output.SetAnimationStreamSource(AnimationStreamSource.PreviousInputs);
            output.SetSortingOrder(sortingOrder);
            // Clip targets are read by a pass-through layer just before this one.
            Sampler = new ClipTargetSampler(_graph, animator, bones, _buffers.Bones, rootBone, (ushort)(sortingOrder - 1));
            // Animator state targets (hand-offs, neural Animator transitions) by a controller copy's reader just before that.
            States = new StateTargetSampler(_graph, animator, _buffers.Bones, rootBone, (ushort)(sortingOrder - 2));
            _graph.Play();
        }

        /// <summary>Reads a clip's pose as a deferred request's target, in the graph's next evaluation.</summary>
        public ClipTargetSampler Sampler { get; }

        /// <summary>Reads an Animator state's pose as a deferred request's target, in the graph's next evaluation.</summary>
        public StateTargetSampler States { get; }

        /// <summary>The latest target asked of either sampler (a clip's or a state's pose), once the evaluation read it; empty before.</summary>
        public ReadOnlySpan<double> Sampled => _stateTargetLatest ? States.Read() : Sampler.Read();

        /// <summary>Asks for a clip's pose (a clip request's target).</summary>
        public void SampleClip(AnimationClip clip, float time)
        {
            Sampler.Sample(clip, time);
            _stateTargetLatest = false;
        }

        /// <summary>Asks for a state's pose (a hand-off's or a neural Animator transition's target).</summary>
        public void SampleState(in StateTarget state)
        {
            States.Sample(state.StateHash, state.Layer, (float)state.Seconds);
            _stateTargetLatest = true;
        }

        /// <summary>The pose the job showed last.</summary>
        public ReadOnlySpan<double> Shown => _buffers.Shown.AsReadOnlySpan();

        /// <summary>
        /// What Unity read for this frame callback: its clock, where the character stands, the controller's root velocity the job
        /// saw on the stream (in the stream's frame), what the Animator applied in the world (<c>Animator.velocity</c>, the
        /// evidence for that frame: Core's <c>RootMotionFrameCheck</c>), the watched layers' state machines.
        /// </summary>
        public CharacterFrameInput Gather(FrameCallback callback)
        {
            if (_playPending) CheckPlayed();
            AnimatorLayerState[] layers = _watcher.Read();
            Vector3 applied = _animator.velocity;
            return new CharacterFrameInput
            {
                Callback = callback,
                ClockMode = (AnimationClockMode)(int)_animator.updateMode,
                DeltaTime = Time.deltaTime,
                UnscaledDeltaTime = Time.unscaledDeltaTime,
                FixedDeltaTime = Time.fixedDeltaTime,
                ApplyRootMotion = _animator.applyRootMotion,
                Place = UnityPoses.Place(_animator.transform),
                ControllerVelocityX = _rootVelocity[3],
                ControllerVelocityY = _rootVelocity[4],
                ControllerVelocityZ = _rootVelocity[5],
                AppliedVelocityX = applied.x,
                AppliedVelocityY = applied.y,
                AppliedVelocityZ = applied.z,
                Layers = layers.Length > 0 ? layers : null,
                LayerCount = layers.Length,
            };
        }

        /// <summary>
        /// Carries out a frame: copies a played frame into the job's buffers, asks for a state's pose the frame wants sampled,
        /// and puts the controller in the state a hand-off arrived in, in this same frame (before the Animator evaluates it), so the
        /// next frames play on in that state. False when the frame failed (the component stops).
        /// </summary>
        public bool Apply(in CharacterFrameOutput frame)
        {
            if (frame.Played) Write(frame);
            // A controller removed since the transition started leaves nothing to read: the deferred request waits until a newer one replaces it.
            if (frame.SampleState && _animator.runtimeAnimatorController != null) SampleState(frame.Sample);
            if (frame.PlayState)
            {
                _animator.PlayInFixedTime(frame.Play.StateHash, frame.Play.Layer, (float)frame.Play.Seconds);
                _playPending = true;
                _playedState = frame.Play.StateHash;
                _playedLayer = frame.Play.Layer;
            }

            return !frame.Failed;
        }

        // The run-time check of the hand-off: a PlayInFixedTime made before the animation update is in effect after it (the
        // Animator is in the state, or already leaving it by one of its transitions). If not, the character popped back: say so once.
        private void CheckPlayed()
        {
            AnimatorStateInfo current = _animator.GetCurrentAnimatorStateInfo(_playedLayer);
            bool entered = current.fullPathHash == _playedState || current.shortNameHash == _playedState;
            _playPending = false;
            if (entered || _warnedPlay) return;
            _warnedPlay = true;
            Debug.LogWarning($"{_animator.name}: the Animator was told to play the hand-off's state (hash {_playedState}, layer {_playedLayer}) in the frame the transition arrived, but it shows another state after the animation update; expected it to play on in that state (a script calling Play in the same frame overrides the hand-off; a culled Animator plays it when it is visible again)", _animator);
        }

        private void Write(in CharacterFrameOutput frame)
        {
            if (frame.RootMotionWarning != null) Debug.LogWarning(_animator.name + ": " + frame.RootMotionWarning, _animator);
            new ReadOnlySpan<double>(frame.Pose).CopyTo(_buffers.Pose.AsSpan());
            _rootVelocity[0] = frame.RootVelocityX;
            _rootVelocity[1] = frame.RootVelocityY;
            _rootVelocity[2] = frame.RootVelocityZ;
            _rootVelocity[6] = frame.RootMotion ? 1 : 0;
            _buffers.Weight[0] = frame.Weight;
        }

        public void Dispose()
        {
            if (_graph.IsValid()) _graph.Destroy();
            Sampler.Dispose();
            States.Dispose();
            if (_keptBones.IsCreated) _keptBones.Dispose();
            _buffers.Dispose();
            if (_rootVelocity.IsCreated) _rootVelocity.Dispose();
        }
    }
}
