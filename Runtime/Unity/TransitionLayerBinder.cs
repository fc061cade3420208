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
    /// layer after the Animator Controller (and a clip target reader just before it), copies each
    /// <see cref="CharacterFrameOutput"/> in, and hands back what the job read (the pose shown, the controller's root
    /// velocity, a sampled target). Pose buffers hold the root position (3 values) then bones × 4 rotation values (w, x, y, z).
    /// </summary>
    internal sealed class TransitionLayerBinder : IDisposable
    {
        private NativeArray<TransformStreamHandle> _bones;
        private NativeArray<double> _pose;
        private NativeArray<double> _shown;
        private NativeArray<double> _weight;
        // [0..2] the transition's root velocity (main thread → job), [3..5] the controller's (job → main thread), [6] 1 with root motion on.
        private NativeArray<double> _rootVelocity;
        private PlayableGraph _graph;
        private readonly Animator _animator;

        /// <summary>
        /// Binds <paramref name="bones"/> of <paramref name="animator"/> (the root bone first) in a graph named
        /// <paramref name="graphName"/> whose output sorts at <paramref name="sortingOrder"/>; until the job first runs, the
        /// pose shown is the bones' pose now.
        /// </summary>
        public TransitionLayerBinder(Animator animator, Transform[] bones, string graphName, ushort sortingOrder)
        {
            const int rootBone = 0;
            _animator = animator;
            double[] initialPose = UnityPoses.Read(bones, rootBone);
            int n = bones.Length;
            _bones = new NativeArray<TransformStreamHandle>(n, Allocator.Persistent);
            for (int b = 0; b < n; b++) _bones[b] = animator.BindStreamTransform(bones[b]);
            _pose = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            _shown = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            _weight = new NativeArray<double>(1, Allocator.Persistent);
            _rootVelocity = new NativeArray<double>(7, Allocator.Persistent);
            // Until the job has run once (it does not while the Animator is culled), the pose shown is the bones' own, never zeros.
            initialPose.CopyTo(_shown.AsSpan());
            var job = new TransitionLayerJob { Bones = _bones, Pose = _pose, Shown = _shown, Weight = _weight, RootVelocity = _rootVelocity, RootBone = rootBone };
            _graph = PlayableGraph.Create(graphName);
            _graph.SetTimeUpdateMode(DirectorUpdateMode.GameTime);
            AnimationPlayableOutput output = AnimationPlayableOutput.Create(_graph, "Δ-Interpolator", animator);
            AnimationScriptPlayable playable = AnimationScriptPlayable.Create(_graph, job);
            output.SetSourcePlayable(playable);
            // Read what the Animator Controller produced (the outputs before this one), then blend over it.
            output.SetAnimationStreamSource(AnimationStreamSource.PreviousInputs);
            output.SetSortingOrder(sortingOrder);
            // Clip targets are read by a pass-through layer just before this one.
            Sampler = new ClipTargetSampler(_graph, animator, bones, _bones, rootBone, (ushort)(sortingOrder - 1));
            _graph.Play();
        }

        /// <summary>Reads a clip's pose as a deferred request's target, in the graph's next evaluation.</summary>
        public ClipTargetSampler Sampler { get; }

        /// <summary>The pose the job showed last.</summary>
        public ReadOnlySpan<double> Shown => _shown.AsReadOnlySpan();

        /// <summary>
        /// What Unity read for this frame callback: its clock, where the character stands, the controller's root velocity the job
        /// saw on the stream (in the stream's frame) and what the Animator applied in the world (<c>Animator.velocity</c>, the
        /// evidence for that frame: Core's <c>RootMotionFrameCheck</c>).
        /// </summary>
        public CharacterFrameInput Gather(FrameCallback callback, Animator animator)
        {
            Vector3 applied = animator.velocity;
            return new CharacterFrameInput
            {
                Callback = callback,
                ClockMode = (AnimationClockMode)(int)animator.updateMode,
                DeltaTime = Time.deltaTime,
                UnscaledDeltaTime = Time.unscaledDeltaTime,
                FixedDeltaTime = Time.fixedDeltaTime,
                ApplyRootMotion = animator.applyRootMotion,
                Place = UnityPoses.Place(animator.transform),
                ControllerVelocityX = _rootVelocity[3],
                ControllerVelocityY = _rootVelocity[4],
                ControllerVelocityZ = _rootVelocity[5],
                AppliedVelocityX = applied.x,
                AppliedVelocityY = applied.y,
                AppliedVelocityZ = applied.z,
            };
        }

        /// <summary>Copies a played frame into the job's buffers; says the frame's root-motion warning (once per character) in the Console.</summary>
        public void Write(in CharacterFrameOutput frame)
        {
            if (frame.RootMotionWarning != null) Debug.LogWarning(_animator.name + ": " + frame.RootMotionWarning, _animator);
            new ReadOnlySpan<double>(frame.Pose).CopyTo(_pose.AsSpan());
            _rootVelocity[0] = frame.RootVelocityX;
            _rootVelocity[1] = frame.RootVelocityY;
            _rootVelocity[2] = frame.RootVelocityZ;
            _rootVelocity[6] = frame.RootMotion ? 1 : 0;
            _weight[0] = frame.Weight;
        }

        public void Dispose()
        {
            if (_graph.IsValid()) _graph.Destroy();
            Sampler.Dispose();
            if (_bones.IsCreated) _bones.Dispose();
            if (_pose.IsCreated) _pose.Dispose();
            if (_shown.IsCreated) _shown.Dispose();
            if (_weight.IsCreated) _weight.Dispose();
            if (_rootVelocity.IsCreated) _rootVelocity.Dispose();
        }
    }
}
