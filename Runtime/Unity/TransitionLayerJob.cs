using System;
using DeltaInterpolator.Core.Playback;
using Unity.Collections;
using UnityEngine.Animations;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The animation job layered after the user's Animator Controller: it blends the transition's pose
    /// (computed on the main thread by Core's <see cref="TransitionPlayer.BeginFrame"/>) over the
    /// controller's output with <see cref="PoseBlend.Apply"/>, and keeps the pose shown for the history.
    /// Pose buffers hold the root position (3 values) then bones × 4 rotation values (w, x, y, z).
    /// </summary>
    internal struct TransitionLayerJob : IAnimationJob
    {
        public NativeArray<TransformStreamHandle> Bones;
        public NativeArray<double> Pose;
        public NativeArray<double> Shown;
        public NativeArray<double> Weight;
        public int RootBone;

        public void ProcessRootMotion(AnimationStream stream)
        {
        }

        public void ProcessAnimation(AnimationStream stream)
        {
            var pose = new AnimatorPoseStream(stream, Bones, RootBone);
            ReadOnlySpan<double> p = Pose.AsReadOnlySpan();
            Span<double> s = Shown.AsSpan();
            PoseBlend.Apply(ref pose, Weight[0], p.Slice(0, 3), p.Slice(3), s.Slice(0, 3), s.Slice(3));
        }
    }
}
