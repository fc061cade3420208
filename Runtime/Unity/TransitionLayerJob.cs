using System;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The animation job layered after the user's Animator Controller: it blends the transition's pose
    /// (computed on the main thread by Core's <see cref="TransitionPlayer.BeginFrame"/> and
    /// <see cref="RootMotion.Plan"/>) over the controller's output with <see cref="PoseBlend.ApplyMasked"/> (bones a masked layer above drives keep the controller's pose), keeps
    /// the pose shown for the history, and blends the transition's root velocity over the controller's
    /// root motion (<see cref="RootMotion.BlendVelocity"/>).
    /// Pose buffers hold the root position (3 values) then bones × 4 rotation values (w, x, y, z).
    /// </summary>
    internal struct TransitionLayerJob : IAnimationJob
    {
        // Shared with the ClipTargetReadJob of the same graph; the handles are only read (the stream is written through them).
        [ReadOnly]
        public NativeArray<TransformStreamHandle> Bones;
        public NativeArray<double> Pose;
        public NativeArray<double> Shown;
        public NativeArray<double> Weight;

        /// <summary>[0..2] the transition's root velocity (in), [3..5] the controller's (out), both per second in the stream's frame; [6] 1 with root motion on.</summary>
        public NativeArray<double> RootVelocity;

        /// <summary>One flag per bone: true where a masked controller layer above drives the bone, which keeps the controller's pose; empty: no mask.</summary>
        /// <remarks>Written once when the binder is built, only read by the job.</remarks>
        [ReadOnly]
        public NativeArray<bool> KeptBones;

        public int RootBone;

        public void ProcessRootMotion(AnimationStream stream)
        {
            // The stream's velocity is the root motion the Animator applies after this job, in a frame Unity's C# does not
            // name (the character's, by Kinematica's WriteRootMotion; Core's RootMotionFrameCheck decides it from
            // Animator.velocity while the game runs). The blend is linear, so it is the same in either frame; the
            // controller's is kept for the main thread's next plan and for that check.
            Vector3 controller = stream.velocity;
            RootVelocity[3] = controller.x;
            RootVelocity[4] = controller.y;
            RootVelocity[5] = controller.z;
            double weight = Weight[0];
            if (weight <= 0 || RootVelocity[6] == 0) return;
            Vector3D blended = RootMotion.BlendVelocity(weight, new Vector3D(RootVelocity[0], RootVelocity[1], RootVelocity[2]), new Vector3D(controller.x, controller.y, controller.z));
            stream.velocity = new Vector3((float)blended.X, (float)blended.Y, (float)blended.Z);
            // The transition's pose carries its own facing (the root bone's rotation): the character turns only
            // by what the controller still shows.
            Vector3 turn = stream.angularVelocity;
            float keep = (float)(1.0 - Math.Min(1.0, weight));
            stream.angularVelocity = new Vector3(turn.x * keep, turn.y * keep, turn.z * keep);
        }

        public void ProcessAnimation(AnimationStream stream)
        {
            var pose = new AnimatorPoseStream(stream, Bones, RootBone);
            ReadOnlySpan<double> p = Pose.AsReadOnlySpan();
            Span<double> s = Shown.AsSpan();
            PoseBlend.ApplyMasked(ref pose, Weight[0], p.Slice(0, 3), p.Slice(3), KeptBones.AsReadOnlySpan(), s.Slice(0, 3), s.Slice(3));
        }
    }
}
