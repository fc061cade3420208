using System;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// What a pose-blending animation job shares with the main thread: the character's bones bound to the Animator's
    /// stream, the pose to lay over them (written by the main thread), the pose the job showed (written by the job) and
    /// the blend weight. The transition layer (<see cref="TransitionLayerBinder"/>) and a Timeline neural track
    /// (<see cref="NeuralBlendLayer"/>) each own one. Pose buffers hold the root position (3 values) then bones × 4
    /// rotation values (w, x, y, z).
    /// </summary>
    internal sealed class PoseBlendBuffers : IDisposable
    {
        /// <summary>Binds <paramref name="bones"/> of <paramref name="animator"/> (persistent buffers; <see cref="Dispose"/> frees them).</summary>
        public PoseBlendBuffers(Animator animator, Transform[] bones)
        {
            int n = bones.Length;
            Bones = new NativeArray<TransformStreamHandle>(n, Allocator.Persistent);
            for (int b = 0; b < n; b++) Bones[b] = animator.BindStreamTransform(bones[b]);
            Pose = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            Shown = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            Weight = new NativeArray<double>(1, Allocator.Persistent);
        }

        // Fields, not properties, as in the jobs that share them: Dispose must reset the arrays it frees (IsCreated false), not copies.

        /// <summary>The bones' stream handles, in the rig's order.</summary>
        public NativeArray<TransformStreamHandle> Bones;

        /// <summary>The pose the job lays over the stream.</summary>
        public NativeArray<double> Pose;

        /// <summary>The pose the job showed last.</summary>
        public NativeArray<double> Shown;

        /// <summary>[0]: how much of <see cref="Pose"/> the job lays over (0: the stream plays as it is).</summary>
        public NativeArray<double> Weight;

        public void Dispose()
        {
            if (Bones.IsCreated) Bones.Dispose();
            if (Pose.IsCreated) Pose.Dispose();
            if (Shown.IsCreated) Shown.Dispose();
            if (Weight.IsCreated) Weight.Dispose();
        }
    }
}
