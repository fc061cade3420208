using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// A character's own animation as a smooth function of time (character space, metres): each bone
    /// swings about its own axis, the root walks forward and bobs. Stands in for the Animator Controller.
    /// </summary>
    public sealed class SyntheticClip
    {
        private readonly Vector3D[] _axes;
        private readonly double[] _amplitudes;
        private readonly double[] _speeds;
        private readonly double[] _phases;
        private readonly QuaternionD[] _rest;

        public SyntheticClip(int bones, int seed)
        {
            var random = new TestRandom(seed);
            _axes = new Vector3D[bones];
            _amplitudes = new double[bones];
            _speeds = new double[bones];
            _phases = new double[bones];
            _rest = new QuaternionD[bones];
            for (int b = 0; b < bones; b++)
            {
                Vector3D axis = random.Vector(1);
                _axes[b] = (1 / axis.Length) * axis;
                _amplitudes[b] = random.Uniform(0.2, 0.8);
                _speeds[b] = random.Uniform(2, 6);
                _phases[b] = random.Uniform(0, 6.28);
                _rest[b] = random.Rotation();
            }
        }

        public int BoneCount => _axes.Length;

        /// <summary>The pose at <paramref name="time"/> seconds, in new arrays (root 3 values, bones × 4 rotation values).</summary>
        public (double[] Root, double[] Rotations) Pose(double time)
        {
            var root = new double[3];
            var rotations = new double[4 * BoneCount];
            Sample(time, root, rotations);
            return (root, rotations);
        }

        /// <summary>The pose at <paramref name="time"/> seconds.</summary>
        public void Sample(double time, double[] root, double[] rotations)
        {
            new Vector3D(0.1 * Math.Sin(0.7 * time), 0.9 + 0.05 * Math.Sin(4 * time), 1.2 * time).Write(root, 0);
            for (int b = 0; b < BoneCount; b++)
            {
                QuaternionD swing = Quaternions.FromAxisAngle(_axes[b], _amplitudes[b] * Math.Sin(_speeds[b] * time + _phases[b]));
                Quaternions.Normalize(Quaternions.Multiply(_rest[b], swing)).Write(rotations, 4 * b);
            }
        }
    }
}
