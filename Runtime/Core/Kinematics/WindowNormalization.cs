using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Kinematics
{
    /// <summary>
    /// The official LaFAN1 benchmark's per-window normalisation (method-spec §1.6–1.7): centre the root's
    /// X and Z on their mean over the window, then turn the window about +Y (the up axis) so that the
    /// character faces a target axis at one frame. Both act on the root only: the root is the one
    /// joint whose local transform is global.
    /// </summary>
    public static class WindowNormalization
    {
        /// <summary>
        /// Subtracts the mean root X and Z over all <paramref name="frameCount"/> frames from every frame;
        /// Y (height) is untouched.
        /// </summary>
        /// <param name="rootPositions">frames × 3 root positions, modified in place.</param>
        /// <param name="frameCount">Number of frames.</param>
        public static void CenterXZ(Span<double> rootPositions, int frameCount)
        {
            if (frameCount <= 0) return;
            double sx = 0, sz = 0;
            for (int f = 0; f < frameCount; f++)
            {
                sx += rootPositions[3 * f];
                sz += rootPositions[3 * f + 2];
            }

            double mx = sx / frameCount, mz = sz / frameCount;
            for (int f = 0; f < frameCount; f++)
            {
                rootPositions[3 * f] -= mx;
                rootPositions[3 * f + 2] -= mz;
            }
        }

        /// <summary>
        /// Turns a window about +Y so that the root faces <paramref name="targetAxis"/> at
        /// <paramref name="facingFrame"/>: with yaw = <see cref="Facing.YawToward"/> of that frame's root
        /// rotation, every root rotation becomes yaw ⊗ q and every root position yaw · p (about the origin,
        /// so centre first as the benchmark does). The official code applies the inverse of
        /// quat_between(target, facing), the same rotation. Other joints' local rotations are relative to
        /// their parents and do not change.
        /// </summary>
        /// <param name="rootPositions">frames × 3, modified in place.</param>
        /// <param name="localRotations">frames × joints × 4, the root's (joint 0) modified in place.</param>
        /// <param name="frameCount">Number of frames.</param>
        /// <param name="jointCount">Joints per frame.</param>
        /// <param name="facingFrame">The frame whose facing is aligned (the benchmark: last past frame, 9).</param>
        /// <param name="localForwardAxis">The root's local forward axis (LaFAN1 hips: +Y).</param>
        /// <param name="targetAxis">The world axis to face (benchmark: +X). Must be horizontal.</param>
        /// <returns>The inverse of the yaw that was applied: apply it to undo.</returns>
        public static QuaternionD FaceAxis(
            Span<double> rootPositions,
            Span<double> localRotations,
            int frameCount,
            int jointCount,
            int facingFrame,
            Vector3D localForwardAxis,
            Vector3D targetAxis)
        {
            if (facingFrame < 0 || facingFrame >= frameCount)
            {
                throw new ArgumentOutOfRangeException(nameof(facingFrame), $"facing frame {facingFrame} is outside the window of {frameCount} frames");
            }

            int stride = jointCount * 4;
            QuaternionD yaw = Facing.YawToward(QuaternionD.Read(localRotations, facingFrame * stride), localForwardAxis, targetAxis);
            for (int f = 0; f < frameCount; f++)
            {
                Quaternions.Multiply(yaw, QuaternionD.Read(localRotations, f * stride)).Write(localRotations, f * stride);
                Quaternions.Apply(yaw, Vector3D.Read(rootPositions, 3 * f)).Write(rootPositions, 3 * f);
            }

            return Quaternions.Conjugate(yaw);
        }
    }
}
