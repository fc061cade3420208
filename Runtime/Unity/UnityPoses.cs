using System;
using DeltaInterpolator.Core.Playback;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Unity's transforms as Core's plain values and back: where a character stands (<see cref="CharacterPlace"/>) and pose
    /// buffers (root position, then bones × 4 rotation values w, x, y, z). Only the component order changes here
    /// (Unity's quaternions are x, y, z, w); the space stays Unity's, the pose converter converts it. The one reader and
    /// writer for everything that samples a clip onto bones and reads them back, or puts a pose on them.
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
            Read(bones, rootBone, pose.AsSpan(0, 3), pose.AsSpan(3));
            return pose;
        }

        /// <summary>Reads the root bone's local position (3 values) and every bone's local rotation (4 each, w first) of <paramref name="bones"/>.</summary>
        public static void Read(Transform[] bones, int rootBone, Span<double> rootPosition, Span<double> localRotations)
        {
            Vector3 p = bones[rootBone].localPosition;
            rootPosition[0] = p.x;
            rootPosition[1] = p.y;
            rootPosition[2] = p.z;
            ReadRotations(bones, localRotations);
        }

        /// <summary>Reads every bone's local rotation (4 values each, w first) of <paramref name="bones"/>.</summary>
        public static void ReadRotations(Transform[] bones, Span<double> localRotations)
        {
            for (int b = 0; b < bones.Length; b++) Write(bones[b].localRotation, localRotations.Slice(4 * b, 4));
        }

        /// <summary>Puts a pose on <paramref name="bones"/>: the root bone's local position and every bone's local rotation.</summary>
        public static void Apply(Transform[] bones, int rootBone, ReadOnlySpan<double> rootPosition, ReadOnlySpan<double> localRotations)
        {
            for (int b = 0; b < bones.Length; b++)
            {
                int at = 4 * b;
                bones[b].localRotation = new Quaternion((float)localRotations[at + 1], (float)localRotations[at + 2], (float)localRotations[at + 3], (float)localRotations[at]);
            }

            bones[rootBone].localPosition = new Vector3((float)rootPosition[0], (float)rootPosition[1], (float)rootPosition[2]);
        }

        /// <summary>Writes <paramref name="q"/> as (w, x, y, z) at <paramref name="at"/>.</summary>
        public static void Write(Quaternion q, double[] values, int at) => Write(q, values.AsSpan(at, 4));

        private static void Write(Quaternion q, Span<double> values)
        {
            values[0] = q.w;
            values[1] = q.x;
            values[2] = q.y;
            values[3] = q.z;
        }
    }
}
