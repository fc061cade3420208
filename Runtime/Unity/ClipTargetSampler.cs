using System;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Samples a clip's pose for a transition target through the component's playable graph, never by
    /// writing to the scene: an <c>AnimationClipPlayable</c> held at the requested time feeds a
    /// <see cref="ClipTargetReadJob"/> on its own pass-through output, which reads the pose in the next
    /// animation evaluation. The component defers the request (Core's <c>TransitionPlayer.DeferTransition</c>)
    /// and completes it when <see cref="TryRead"/> has the pose, with the arrival time asked for.
    /// </summary>
    /// <remarks>
    /// The output sorts just before the component's transition layer and passes the controller's pose on
    /// unchanged (the job writes nothing); the clip is evaluated only in frames that sample a target. Foot
    /// IK and playable IK are off, so the pose is the clip's own, as <c>AnimationClip.SampleAnimation</c> gives it.
    /// The graph owns the playables (destroying it destroys them); <see cref="Dispose"/> frees the buffers.
    /// </remarks>
    internal sealed class ClipTargetSampler : IDisposable
    {
        private readonly PlayableGraph _graph;
        private readonly TargetPoseReader _reader;
        private AnimationClipPlayable _clipPlayable;
        private AnimationClip? _clip;
        private float _time;
        private readonly HumanoidTargetCheck _check;

        public ClipTargetSampler(PlayableGraph graph, Animator animator, Transform[] boneTransforms, NativeArray<TransformStreamHandle> bones, int rootBone, ushort sortingOrder)
        {
            _graph = graph;
            _check = new HumanoidTargetCheck(animator, boneTransforms);
            _reader = new TargetPoseReader(graph, animator, bones, rootBone, sortingOrder, "Δ-Interpolator target");
        }

        /// <summary>Asks for the pose <paramref name="clip"/> shows at <paramref name="time"/>; it is read in the next animation evaluation.</summary>
        public void Sample(AnimationClip clip, float time)
        {
            if (clip != _clip)
            {
                if (_clip != null) _graph.DestroyPlayable(_clipPlayable);
                _clipPlayable = AnimationClipPlayable.Create(_graph, clip);
                _clipPlayable.SetApplyFootIK(false);
                _clipPlayable.SetApplyPlayableIK(false);
                // Held at the requested time: the graph's clock must not move it before it is read.
                _clipPlayable.Pause();
                _graph.Connect(_clipPlayable, 0, _reader.Playable, 0);
                _clip = clip;
            }

            _clipPlayable.SetTime(time);
            _time = time;
            _reader.Ask();
        }

        /// <summary>
        /// The pose of the latest <see cref="Sample"/> (root position, then bones × 4 rotations) once the animation
        /// evaluation has read it; empty while it has not (e.g. the Animator was culled and did not evaluate).
        /// </summary>
        public ReadOnlySpan<double> Read()
        {
            ReadOnlySpan<double> pose = _reader.Read();
            if (pose.IsEmpty) return default;
            // Humanoid targets come off a path no Unity code demonstrates: held once per clip against SampleAnimation's.
            _check.Check(_clip!, _time, pose);
            return pose;
        }

        public void Dispose()
        {
            _check.Dispose();
            _reader.Dispose();
        }
    }
}
