using System;
using BenchmarkDotNet.Attributes;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Benchmarks
{
    /// <summary>
    /// One pose through <see cref="SkeletonMap"/> per call, as the Unity component converts a character's
    /// pose each frame: a CMU-sized source (31 joints, with joints the model lacks) onto LaFAN1's 22 joints
    /// and back. Both must report 0 B allocated (MemoryDiagnoser).
    /// </summary>
    [MemoryDiagnoser]
    public class RetargetBenchmarks
    {
        private SkeletonMap _map = null!;
        private double[] _sourcePositions = null!;
        private double[] _sourceRotations = null!;
        private double[] _targetRoot = null!;
        private double[] _targetRotations = null!;

        [GlobalSetup]
        public void Setup()
        {
            // LaFAN1's joints and offsets (cm), the model's skeleton.
            string[] lafan =
            {
                "Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToe", "RightUpLeg", "RightLeg", "RightFoot", "RightToe",
                "Spine", "Spine1", "Spine2", "Neck", "Head", "LeftShoulder", "LeftArm", "LeftForeArm", "LeftHand",
                "RightShoulder", "RightArm", "RightForeArm", "RightHand",
            };
            int[] lafanParents = { -1, 0, 1, 2, 3, 0, 5, 6, 7, 0, 9, 10, 11, 12, 11, 14, 15, 16, 11, 18, 19, 20 };
            double[] lafanOffsets =
            {
                0, 0, 0, 0.1, 1.86, 10.55, 43.5, 0, 0, 42.37, 0, 0, 17.3, 0, 0, 0.1, 1.86, -10.55, 43.5, 0, 0, 42.37, 0, 0, 17.3, 0, 0,
                6.9, -2.6, 0, 12.59, 0, 0, 12.34, 0, 0, 25.83, 0, 0, 11.77, 0, 0, 19.75, -1.48, 6.0, 11.28, 0, 0, 33.0, 0, 0, 25.2, 0, 0,
                19.75, -1.48, -6.0, 11.28, 0, 0, 33.0, 0, 0, 25.2, 0, 0,
            };
            var model = new Skeleton(lafan, lafanParents, lafanOffsets);

            // The CMU conversion's 31 joints with its subject-1 offsets (units of 0.056444 m).
            string[] cmu =
            {
                "Hips", "LHipJoint", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase", "RHipJoint", "RightUpLeg", "RightLeg", "RightFoot", "RightToeBase",
                "LowerBack", "Spine", "Spine1", "Neck", "Neck1", "Head", "LeftShoulder", "LeftArm", "LeftForeArm", "LeftHand", "LeftFingerBase",
                "LeftHandIndex1", "LThumb", "RightShoulder", "RightArm", "RightForeArm", "RightHand", "RightFingerBase", "RightHandIndex1", "RThumb",
            };
            int[] cmuParents = { -1, 0, 1, 2, 3, 4, 0, 6, 7, 8, 9, 0, 11, 12, 13, 14, 15, 13, 17, 18, 19, 20, 21, 20, 13, 24, 25, 26, 27, 28, 27 };
            double[] cmuOffsets =
            {
                0, 0, 0, 0, 0, 0, 1.36, -1.79, 0.84, 2.45, -6.73, 0, 2.56, -7.04, 0, 0.16, -0.43, 2.32,
                0, 0, 0, -1.31, -1.79, 0.84, -2.54, -6.99, 0, -2.57, -7.06, 0, -0.16, -0.45, 2.36,
                0, 0, 0, 0.03, 2.04, -0.19, 0.06, 2.05, -0.04, 0, 0, 0, -0.05, 1.75, 0.17, 0.1, 1.76, -0.12,
                0, 0, 0, 3.36, 1.2, -0.31, 4.98, 0, 0, 3.48, 0, 0, 0, 0, 0, 0.72, 0, 0, 0, 0, 0,
                0, 0, 0, -3.36, 1.2, -0.31, -4.98, 0, 0, -3.48, 0, 0, 0, 0, 0, -0.72, 0, 0, 0, 0, 0,
            };
            var source = new Skeleton(cmu, cmuParents, cmuOffsets);
            _map = SkeletonMap.Create(ReferencePose.Zero(source), ReferencePose.ModelTPose(model), null, "benchmark");

            var random = new Random(3);
            _sourcePositions = new double[3 * source.JointCount];
            source.OffsetSpan.CopyTo(_sourcePositions);
            _sourcePositions[1] = 17.0;
            _sourceRotations = new double[4 * source.JointCount];
            for (int j = 0; j < source.JointCount; j++)
            {
                var q = new QuaternionD(1.0, 0.3 * (random.NextDouble() - 0.5), 0.3 * (random.NextDouble() - 0.5), 0.3 * (random.NextDouble() - 0.5));
                Quaternions.Normalize(q).Write(_sourceRotations, 4 * j);
            }

            _targetRoot = new double[3];
            _targetRotations = new double[4 * model.JointCount];
            _map.ToTargetFrame(_sourcePositions, _sourceRotations, _targetRoot, _targetRotations);
        }

        /// <summary>A CMU pose onto the model's skeleton.</summary>
        [Benchmark]
        public double ToTargetFrame()
        {
            _map.ToTargetFrame(_sourcePositions, _sourceRotations, _targetRoot, _targetRotations);
            return _targetRotations[0];
        }

        /// <summary>A model pose back onto the CMU skeleton, in place.</summary>
        [Benchmark]
        public double ToSourceFrame()
        {
            _map.ToSourceFrame(Vector3D.Read(_targetRoot, 0), _targetRotations, _sourcePositions, _sourceRotations);
            return _sourceRotations[0];
        }
    }
}
