using System;
using BenchmarkDotNet.Attributes;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Benchmarks
{
    /// <summary>
    /// <see cref="ClipBaker"/>'s own work around the in-betweener: one minute of 30 fps motion (1,800
    /// frames, 22 joints) with a key every 15 frames, baked with SLERP into the same clip again. Must
    /// report 0 B allocated (the model's share is the network: ./Tools~/inbetween speed).
    /// </summary>
    [MemoryDiagnoser]
    public class BakeBenchmarks
    {
        private const int Joints = 22;
        private const int Frames = 1800;

        private ClipBaker _baker = null!;
        private MotionClip _source = null!;
        private MotionClip _baked = null!;
        private BakePlan _plan = null!;

        [GlobalSetup]
        public void Setup()
        {
            int[] parents = { -1, 0, 1, 2, 3, 0, 5, 6, 7, 0, 9, 10, 11, 12, 11, 14, 15, 16, 11, 18, 19, 20 };
            var names = new string[Joints];
            var offsets = new double[3 * Joints];
            var random = new Random(1);
            for (int j = 0; j < Joints; j++)
            {
                names[j] = "joint" + j;
                for (int c = 0; c < 3; c++) offsets[3 * j + c] = j == 0 ? 0 : 20 * (random.NextDouble() - 0.5);
            }

            var skeleton = new Skeleton(names, parents, offsets);
            _source = MotionClip.CreateRestPose(skeleton, Frames, 1.0 / 30);
            for (int f = 0; f < Frames; f++)
            {
                for (int c = 0; c < 3; c++) _source.LocalPositions[_source.PositionIndex(f, 0) + c] = 100 * random.NextDouble();
                for (int j = 0; j < Joints; j++)
                {
                    var axis = new Vector3D(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                    Quaternions.FromAxisAngle((1.0 / axis.Length) * axis, 3 * random.NextDouble()).Write(_source.LocalRotations, _source.RotationIndex(f, j));
                }
            }

            _baker = new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline());
            _plan = _baker.Plan(Frames, KeyFrames.Every(15, Frames));
            _baked = _baker.Bake(_source, _plan);
        }

        /// <summary>1,800 frames, 120 gaps of 14 frames, SLERP, into the same clip.</summary>
        [Benchmark]
        public void SlerpBakeOneMinute() => _baker.Bake(_source, _plan, _baked);
    }
}
