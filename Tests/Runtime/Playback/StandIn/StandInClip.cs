using System;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// A real motion-capture clip as a stand-in controller plays it: a CMU take retargeted onto the model's skeleton (as the
    /// retargeting tests do), resampled to 30 fps and converted to the character's space, its root split into the travel
    /// on the ground (the root motion, x and z) and the root bone's height above it (the in-place pose).
    /// </summary>
    public sealed class StandInClip
    {
        private const double FrameTime = 1.0 / 30.0;
        private readonly double[] _travel;      // frames × 2 (x, z): the root's position on the ground
        private readonly double[] _height;      // frames: the root's height
        private readonly double[] _rotations;   // frames × bones × 4
        private readonly int _bones;

        /// <summary>Loads <paramref name="file"/> (a name under ../shared/data/cmu) for a character of <paramref name="converter"/>'s bones on <paramref name="model"/>'s skeleton.</summary>
        public StandInClip(string file, Skeleton model, IPoseConverter converter)
        {
            string path = Path.Combine(Retargeting.RetargetFixtures.RequireCmu(), file);
            if (!File.Exists(path)) Assert.Ignore($"{path} not found; skipping.");
            BvhAnimation cmu = BvhReader.Read(path);
            SkeletonMap map = SkeletonMap.Create(ReferencePose.FromFrame(cmu.Motion, 0), ReferencePose.ModelTPose(model), null, path);
            // Frame 0 of a CMU take is its T-pose: the clip starts at frame 1.
            MotionClip onModel = MotionResampler.Resample(map.ToTarget(cmu.Motion), FrameTime);
            Name = Path.GetFileNameWithoutExtension(file);
            _bones = converter.BoneCount;
            int first = (int)Math.Ceiling(cmu.Motion.FrameTime / FrameTime);
            FrameCount = onModel.FrameCount - first;
            _travel = new double[2 * FrameCount];
            _height = new double[FrameCount];
            _rotations = new double[4 * _bones * FrameCount];
            int j = onModel.Skeleton.JointCount;
            var modelRoot = new double[3];
            var modelRotations = new double[4 * j];
            var root = new double[3];
            var rotations = new double[4 * _bones];
            for (int f = 0; f < FrameCount; f++)
            {
                for (int k = 0; k < 3; k++) modelRoot[k] = onModel.LocalPositions[onModel.PositionIndex(first + f, 0) + k];
                Array.Copy(onModel.LocalRotations, onModel.RotationIndex(first + f, 0), modelRotations, 0, 4 * j);
                converter.ToCharacter(modelRoot, modelRotations, root, rotations);
                _travel[2 * f] = root[0];
                _travel[2 * f + 1] = root[2];
                _height[f] = root[1];
                Array.Copy(rotations, 0, _rotations, 4 * _bones * f, 4 * _bones);
            }
        }

        /// <summary>Bones per pose.</summary>
        public int BoneCount => _bones;

        /// <summary>The take's name (e.g. 07_01).</summary>
        public string Name { get; }

        /// <summary>Frames at 30 fps.</summary>
        public int FrameCount { get; }

        /// <summary>Seconds from the first frame to the last.</summary>
        public double Length => (FrameCount - 1) * FrameTime;

        /// <summary>
        /// The clip at <paramref name="time"/> (clamped to the clip; frames interpolated): the root's height, every bone's rotation,
        /// and where the root stands on the ground (x, z).
        /// </summary>
        public void Sample(double time, out double height, Span<double> rotations, out double travelX, out double travelZ)
        {
            double u = Math.Max(0, Math.Min(FrameCount - 1.000001, time / FrameTime));
            int a = (int)Math.Floor(u);
            double f = u - a;
            height = _height[a] + f * (_height[a + 1] - _height[a]);
            travelX = _travel[2 * a] + f * (_travel[2 * a + 2] - _travel[2 * a]);
            travelZ = _travel[2 * a + 1] + f * (_travel[2 * a + 3] - _travel[2 * a + 1]);
            int r = 4 * _bones;
            for (int b = 0; b < _bones; b++)
            {
                QuaternionD qa = QuaternionD.Read(_rotations, r * a + 4 * b);
                QuaternionD qb = QuaternionD.Read(_rotations, r * (a + 1) + 4 * b);
                Quaternions.Normalize(Quaternions.Slerp(qa, qb, f)).Write(rotations, 4 * b);
            }
        }
    }
}
