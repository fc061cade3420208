using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Tests.Preview
{
    /// <summary>Motion for the preview tests: a small synthetic walker, LaFAN1 excerpts, SLERP-baked and perturbed copies.</summary>
    internal static class PreviewMotion
    {
        /// <summary>A 15-joint figure walking along +Z with swinging arms and legs, Y up, centimetres.</summary>
        public static MotionClip Walker(int frames, double frameTime = 1.0 / 30)
        {
            string[] names = { "Hips", "Spine", "Neck", "Head", "LeftArm", "LeftForeArm", "LeftHand", "RightArm", "RightForeArm", "RightHand", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg", "RightLeg", "RightFoot" };
            int[] parents = { -1, 0, 1, 2, 2, 4, 5, 2, 7, 8, 0, 10, 11, 0, 13, 14 };
            double[] offsets =
            {
                0, 95, 0, 0, 25, 0, 0, 25, 0, 0, 15, 0,
                18, -5, 0, 0, -28, 0, 0, -25, 0,
                -18, -5, 0, 0, -28, 0, 0, -25, 0,
                10, -5, 0, 0, -42, 0, 0, -42, 0,
                -10, -5, 0, 0, -42, 0, 0, -42, 0,
            };
            var skeleton = new Skeleton(names, parents, offsets);
            int j = names.Length;
            var positions = new double[frames * j * 3];
            var rotations = new double[frames * j * 4];
            var xAxis = new Vector3D(1, 0, 0);
            for (int f = 0; f < frames; f++)
            {
                double phase = 2 * Math.PI * f / 32.0;
                offsets.CopyTo(positions, f * j * 3);
                positions[f * j * 3] = 4 * Math.Sin(phase / 2);
                positions[f * j * 3 + 1] = 95 + 2 * Math.Cos(2 * phase);
                positions[f * j * 3 + 2] = 3.5 * f;
                for (int k = 0; k < j; k++)
                {
                    double angle = k switch
                    {
                        4 => 0.6 * Math.Sin(phase),
                        5 => -0.4 - 0.3 * Math.Sin(phase),
                        7 => -0.6 * Math.Sin(phase),
                        8 => -0.4 + 0.3 * Math.Sin(phase),
                        10 => -0.5 * Math.Sin(phase),
                        11 => 0.5 + 0.5 * Math.Cos(phase),
                        13 => 0.5 * Math.Sin(phase),
                        14 => 0.5 - 0.5 * Math.Cos(phase),
                        _ => 0,
                    };
                    Quaternions.FromAxisAngle(xAxis, angle).Write(rotations, (f * j + k) * 4);
                }
            }

            return new MotionClip(skeleton, frames, frameTime, positions, rotations);
        }

        /// <summary>Frames [start, start + count) of a clip.</summary>
        public static MotionClip Excerpt(MotionClip clip, int start, int count)
        {
            int j = clip.Skeleton.JointCount;
            var positions = new double[count * j * 3];
            var rotations = new double[count * j * 4];
            Array.Copy(clip.LocalPositions, start * j * 3, positions, 0, positions.Length);
            Array.Copy(clip.LocalRotations, start * j * 4, rotations, 0, rotations.Length);
            return new MotionClip(clip.Skeleton, count, clip.FrameTime, positions, rotations);
        }

        /// <summary>
        /// The clip with every gap between consecutive <paramref name="keys"/> filled by Core's
        /// <see cref="SlerpBaseline"/> (root LERP, local rotations SLERP); key frames and frames outside
        /// the keys stay as they are.
        /// </summary>
        public static MotionClip SlerpBaked(MotionClip clip, IReadOnlyList<int> keys)
        {
            int j = clip.Skeleton.JointCount;
            var positions = (double[])clip.LocalPositions.Clone();
            var rotations = (double[])clip.LocalRotations.Clone();
            var slerp = new SlerpBaseline();
            for (int i = 0; i + 1 < keys.Count; i++)
            {
                int a = keys[i], b = keys[i + 1], n = b - a - 1;
                if (n <= 0) continue;
                var transition = new Transition(clip.Skeleton, 1, n);
                Array.Copy(clip.LocalPositions, a * j * 3, transition.KeyRootPositions, 0, 3);
                Array.Copy(clip.LocalPositions, b * j * 3, transition.KeyRootPositions, 3, 3);
                Array.Copy(clip.LocalRotations, a * j * 4, transition.KeyLocalRotations, 0, j * 4);
                Array.Copy(clip.LocalRotations, b * j * 4, transition.KeyLocalRotations, j * 4, j * 4);
                slerp.Inbetween(transition);
                for (int k = 0; k < n; k++)
                {
                    int f = a + 1 + k;
                    Array.Copy(transition.RootPositions, k * 3, positions, f * j * 3, 3);
                    Array.Copy(transition.LocalRotations, k * j * 4, rotations, f * j * 4, j * 4);
                }
            }

            return new MotionClip(clip.Skeleton, clip.FrameCount, clip.FrameTime, positions, rotations);
        }

        /// <summary>The clip with each joint's local rotation turned by a slow, joint-dependent wobble of up to <paramref name="degrees"/>.</summary>
        public static MotionClip Wobbled(MotionClip clip, double degrees)
        {
            int j = clip.Skeleton.JointCount;
            var rotations = (double[])clip.LocalRotations.Clone();
            for (int f = 0; f < clip.FrameCount; f++)
            {
                for (int k = 0; k < j; k++)
                {
                    double angle = degrees * Math.PI / 180 * Math.Sin(2 * Math.PI * f / 40.0 + k);
                    var axis = new Vector3D(Math.Cos(k), 0.5, Math.Sin(k));
                    QuaternionD wobble = Quaternions.FromAxisAngle((1 / Math.Sqrt(1.25)) * axis, angle);
                    int i = (f * j + k) * 4;
                    Quaternions.Multiply(QuaternionD.Read(rotations, i), wobble).Write(rotations, i);
                }
            }

            return new MotionClip(clip.Skeleton, clip.FrameCount, clip.FrameTime, (double[])clip.LocalPositions.Clone(), rotations);
        }

        /// <summary>Key frames every <paramref name="every"/> frames from 0, plus the last frame.</summary>
        public static int[] KeysEvery(int frames, int every)
        {
            var keys = Enumerable.Range(0, (frames - 1) / every + 1).Select(i => i * every).ToList();
            if (keys[keys.Count - 1] != frames - 1) keys.Add(frames - 1);
            return keys.ToArray();
        }

        /// <summary>A LaFAN1 subject-5 file (skips the test when the data is absent).</summary>
        public static BvhAnimation Lafan(string name)
        {
            string dir = TestEnvironment.RequireLafan1();
            return BvhReader.Read(Path.Combine(dir, name));
        }
    }
}
