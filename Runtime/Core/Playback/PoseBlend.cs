using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Blends a transition's pose over the pose in an <see cref="IPoseStream"/> (what the user's Animator
    /// Controller produced) and writes the result back, keeping a copy of what is shown for the history.
    /// Runs wherever the stream is evaluated (Unity: the animation job's <c>ProcessAnimation</c>).
    /// </summary>
    public static class PoseBlend
    {
        /// <summary>
        /// shown = slerp(stream, pose, weight) per bone (lerp for the root); weight 0 leaves the stream
        /// untouched, weight 1 shows <paramref name="poseRotations"/> exactly.
        /// </summary>
        /// <param name="stream">The pose being evaluated; read, then written when weight &gt; 0.</param>
        /// <param name="weight">0 (the controller's pose) to 1 (the transition's pose).</param>
        /// <param name="poseRoot">The transition's root position (3).</param>
        /// <param name="poseRotations">The transition's local rotations (bones × 4).</param>
        /// <param name="shownRoot">Receives the root position shown (3).</param>
        /// <param name="shownRotations">Receives the local rotations shown (bones × 4).</param>
        public static void Apply<TStream>(ref TStream stream, double weight, ReadOnlySpan<double> poseRoot, ReadOnlySpan<double> poseRotations, Span<double> shownRoot, Span<double> shownRotations)
            where TStream : IPoseStream
        {
            ApplyMasked(ref stream, weight, poseRoot, poseRotations, ReadOnlySpan<bool>.Empty, shownRoot, shownRotations);
        }

        /// <summary>
        /// <see cref="Apply"/> with a bone
        /// mask: a bone whose <paramref name="keptBones"/> entry is true keeps the stream's rotation (the bones a masked controller layer above
        /// the replaced one drives; Unity: built from that layer's <c>AvatarMask</c>), and the root position is kept with bone 0.
        /// </summary>
        /// <param name="stream">The pose being evaluated; read, then written where the transition shows.</param>
        /// <param name="weight">0 (the controller's pose) to 1 (the transition's pose).</param>
        /// <param name="poseRoot">The transition's root position (3).</param>
        /// <param name="poseRotations">The transition's local rotations (bones × 4).</param>
        /// <param name="keptBones">Per bone, true: the stream's pose stays; empty: no bone is kept.</param>
        /// <param name="shownRoot">Receives the root position shown (3).</param>
        /// <param name="shownRotations">Receives the local rotations shown (bones × 4).</param>
        /// <exception cref="ArgumentException"><paramref name="keptBones"/> is neither empty nor one entry per bone.</exception>
        public static void ApplyMasked<TStream>(ref TStream stream, double weight, ReadOnlySpan<double> poseRoot, ReadOnlySpan<double> poseRotations, ReadOnlySpan<bool> keptBones, Span<double> shownRoot, Span<double> shownRotations)
            where TStream : IPoseStream
        {
            int bones = stream.BoneCount;
            if (keptBones.Length != 0 && keptBones.Length != bones) throw new ArgumentException($"a bone mask has one entry per bone ({bones}), not {keptBones.Length}", nameof(keptBones));
            if (keptBones.Length != 0 && weight > 0)
            {
                Masked(ref stream, weight, poseRoot, poseRotations, keptBones, shownRoot, shownRotations);
                return;
            }

            if (weight <= 0)
            {
                stream.ReadRootPosition().Write(shownRoot, 0);
                for (int b = 0; b < bones; b++) stream.ReadLocalRotation(b).Write(shownRotations, 4 * b);
                return;
            }

            if (weight >= 1)
            {
                Vector3D root = Vector3D.Read(poseRoot, 0);
                stream.WriteRootPosition(root);
                root.Write(shownRoot, 0);
                for (int b = 0; b < bones; b++)
                {
                    QuaternionD q = QuaternionD.Read(poseRotations, 4 * b);
                    stream.WriteLocalRotation(b, q);
                    q.Write(shownRotations, 4 * b);
                }

                return;
            }

            Vector3D from = stream.ReadRootPosition();
            Vector3D blended = from + weight * (Vector3D.Read(poseRoot, 0) - from);
            stream.WriteRootPosition(blended);
            blended.Write(shownRoot, 0);
            for (int b = 0; b < bones; b++)
            {
                QuaternionD q = Quaternions.Normalize(new SlerpPair(stream.ReadLocalRotation(b), QuaternionD.Read(poseRotations, 4 * b)).At(weight));
                stream.WriteLocalRotation(b, q);
                q.Write(shownRotations, 4 * b);
            }
        }

        // Weight > 0 with a mask: per bone, the stream's rotation where kept, the blend elsewhere.
        private static void Masked<TStream>(ref TStream stream, double weight, ReadOnlySpan<double> poseRoot, ReadOnlySpan<double> poseRotations, ReadOnlySpan<bool> keptBones, Span<double> shownRoot, Span<double> shownRotations)
            where TStream : IPoseStream
        {
            Vector3D from = stream.ReadRootPosition();
            Vector3D root = keptBones[0] ? from : weight >= 1 ? Vector3D.Read(poseRoot, 0) : from + weight * (Vector3D.Read(poseRoot, 0) - from);
            stream.WriteRootPosition(root);
            root.Write(shownRoot, 0);
            for (int b = 0; b < keptBones.Length; b++)
            {
                QuaternionD own = stream.ReadLocalRotation(b);
                QuaternionD q = keptBones[b] ? own : weight >= 1 ? QuaternionD.Read(poseRotations, 4 * b) : Quaternions.Normalize(new SlerpPair(own, QuaternionD.Read(poseRotations, 4 * b)).At(weight));
                stream.WriteLocalRotation(b, q);
                q.Write(shownRotations, 4 * b);
            }
        }
    }
}
