using System;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Bones' local transforms as Core's pose buffers, in Unity's space: the first bone's local position as the root
    /// position and every bone's local rotation as (w, x, y, z). One reader for everything that samples a clip onto
    /// bones and reads them back (clip poses, the baker's sampler, the key fill's scene pose, the humanoid check).
    /// </summary>
    internal static class BonePose
    {
        /// <summary>Reads the root position (3) and the local rotations (4 per bone) of <paramref name="bones"/>.</summary>
        public static void Read(Transform[] bones, Span<double> rootPosition, Span<double> localRotations)
        {
            Vector3 p = bones[0].localPosition;
            rootPosition[0] = p.x;
            rootPosition[1] = p.y;
            rootPosition[2] = p.z;
            ReadRotations(bones, localRotations);
        }

        /// <summary>Reads the local rotations (4 per bone, w first) of <paramref name="bones"/>.</summary>
        public static void ReadRotations(Transform[] bones, Span<double> localRotations)
        {
            for (int b = 0; b < bones.Length; b++)
            {
                Quaternion q = bones[b].localRotation;
                localRotations[4 * b] = q.w;
                localRotations[4 * b + 1] = q.x;
                localRotations[4 * b + 2] = q.y;
                localRotations[4 * b + 3] = q.z;
            }
        }
    }
}
