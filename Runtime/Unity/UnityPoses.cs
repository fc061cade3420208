using DeltaInterpolator.Core.Playback;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Unity's transforms as Core's plain values: where a character stands (<see cref="CharacterPlace"/>) and pose
    /// buffers (root position, then bones × 4 rotation values w, x, y, z). Only the component order changes here
    /// (Unity's quaternions are x, y, z, w); the space stays Unity's, the pose converter converts it.
    /// </summary>
    internal static class UnityPoses
    {
        /// <summary>Where <paramref name="t"/> stands in the world (position, rotation, uniform scale).</summary>
        public static CharacterPlace Place(Transform t)
        {
            Vector3 p = t.position;
            Quaternion q = t.rotation;
            return new CharacterPlace { X = p.x, Y = p.y, Z = p.z, RotationW = q.w, RotationX = q.x, RotationY = q.y, RotationZ = q.z, Scale = t.lossyScale.x };
        }

        /// <summary>A pose buffer of <paramref name="bones"/> as they are now (the root bone's local position, every bone's local rotation).</summary>
        public static double[] Read(Transform[] bones, int rootBone)
        {
            var pose = new double[3 + 4 * bones.Length];
            Vector3 p = bones[rootBone].localPosition;
            pose[0] = p.x;
            pose[1] = p.y;
            pose[2] = p.z;
            for (int b = 0; b < bones.Length; b++) Write(bones[b].localRotation, pose, 3 + 4 * b);
            return pose;
        }

        /// <summary>Writes <paramref name="q"/> as (w, x, y, z) at <paramref name="at"/>.</summary>
        public static void Write(Quaternion q, double[] values, int at)
        {
            values[at] = q.w;
            values[at + 1] = q.x;
            values[at + 2] = q.y;
            values[at + 3] = q.z;
        }
    }
}
