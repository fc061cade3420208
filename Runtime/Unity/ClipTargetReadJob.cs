using DeltaInterpolator.Core.Rotations;
using Unity.Collections;
using UnityEngine.Animations;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Reads a requested target pose from the clip playing into this job's input (the
    /// <see cref="ClipTargetSampler"/>'s <c>AnimationClipPlayable</c>), in the frame's animation evaluation,
    /// into <see cref="Target"/>: the root bone's local position (3 values) then the bones' local rotations
    /// (bones × 4, w x y z), the layout the component's requests use. It writes nothing to its own stream,
    /// so its output passes the Animator's pose through unchanged; inputs are not processed automatically
    /// (<c>SetProcessInputs(false)</c>), so the clip is evaluated only in a frame that asks for a target.
    /// </summary>
    internal struct ClipTargetReadJob : IAnimationJob
    {
        // Shared with the TransitionLayerJob of the same graph: neither writes the handles, and saying so lets the job
        // system's safety checks schedule both over one array.
        [ReadOnly]
        public NativeArray<TransformStreamHandle> Bones;
        public NativeArray<double> Target;

        /// <summary>[0] the request to read (main thread writes), [1] the last request read (the job writes).</summary>
        public NativeArray<int> Requests;

        public int RootBone;

        public void ProcessRootMotion(AnimationStream stream)
        {
        }

        public void ProcessAnimation(AnimationStream stream)
        {
            if (Requests[0] == Requests[1] || stream.inputStreamCount < 1) return;
            AnimationStream clip = stream.GetInputStream(0);
            if (!clip.isValid) return;
            var pose = new AnimatorPoseStream(clip, Bones, RootBone);
            Vector3D root = pose.ReadRootPosition();
            Target[0] = root.X;
            Target[1] = root.Y;
            Target[2] = root.Z;
            for (int b = 0; b < Bones.Length; b++)
            {
                QuaternionD q = pose.ReadLocalRotation(b);
                Target[3 + 4 * b] = q.W;
                Target[4 + 4 * b] = q.X;
                Target[5 + 4 * b] = q.Y;
                Target[6 + 4 * b] = q.Z;
            }

            Requests[1] = Requests[0];
        }
    }
}
