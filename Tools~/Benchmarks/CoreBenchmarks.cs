using System;
using BenchmarkDotNet.Attributes;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Benchmarks
{
    /// <summary>
    /// The per-transition Core work around the network for a LaFAN1-sized request: 22 joints, P = 10,
    /// n = 30. Every benchmark must report 0 B allocated (MemoryDiagnoser).
    /// </summary>
    [MemoryDiagnoser]
    public class CoreBenchmarks
    {
        private const int Joints = 22;
        private const int Past = 10;
        private const int Missing = 30;

        private Skeleton _skeleton = null!;
        private Transition _transition = null!;
        private SlerpBaseline _slerp = null!;
        private double[] _positions = null!;
        private double[] _rotations = null!;
        private float[] _deltas = null!;
        private QuaternionD[] _baselines = null!;
        private double[] _localRoot = null!;
        private double[] _localRotations = null!;
        private float[] _features = null!;
        private KeyFeatureBuilder _builder = null!;

        [GlobalSetup]
        public void Setup()
        {
            // LaFAN1's hierarchy (parents) with bone-like offsets.
            int[] parents = { -1, 0, 1, 2, 3, 0, 5, 6, 7, 0, 9, 10, 11, 12, 11, 14, 15, 16, 11, 18, 19, 20 };
            var names = new string[Joints];
            var offsets = new double[3 * Joints];
            var random = new Random(1);
            for (int j = 0; j < Joints; j++)
            {
                names[j] = "joint" + j;
                for (int c = 0; c < 3; c++) offsets[3 * j + c] = j == 0 ? 0 : 20 * (random.NextDouble() - 0.5);
            }

            _skeleton = new Skeleton(names, parents, offsets);
            _transition = new Transition(_skeleton, Past, Missing);
            for (int i = 0; i < _transition.KeyRootPositions.Length; i++) _transition.KeyRootPositions[i] = 100 * random.NextDouble();
            for (int i = 0; i < _transition.KeyLocalRotations.Length; i += 4)
            {
                RandomRotation(random).Write(_transition.KeyLocalRotations, i);
            }

            _slerp = new SlerpBaseline();
            _slerp.Inbetween(_transition);
            _positions = new double[Missing * Joints * 3];
            _rotations = new double[Missing * Joints * 4];
            _deltas = new float[Missing * Joints * 6];
            for (int i = 0; i < _deltas.Length; i++) _deltas[i] = (float)(0.05 * (random.NextDouble() - 0.5));
            _baselines = new QuaternionD[Missing * Joints];
            for (int i = 0; i < _baselines.Length; i++) _baselines[i] = RandomRotation(random);

            string meta = "{\"contract_version\": 1, \"graph\": \"whole\", \"skeleton\": {\"names\": [" + string.Join(", ", Array.ConvertAll(names, n => "\"" + n + "\"")) +
                          "], \"parents\": [" + string.Join(", ", parents) + "], \"offsets\": [" + Offsets(offsets) + "]}, \"unit_scale\": 0.01, \"up_axis\": [0, 1, 0], " +
                          "\"facing_local_axis\": [0, 1, 0], \"facing_target_axis\": [1, 0, 0], \"rotation_6d\": \"rows\", \"quaternion_order\": \"wxyz\", " +
                          "\"output_delta_mode\": \"slerp\", \"input_delta_mode\": \"last_pose\", \"architecture\": {\"width\": 256, \"blocks\": 4, \"heads\": 8, \"embedding_dim\": 32, \"embedding_size\": 256}}";
            ModelContract contract = ModelContract.Read(Description(meta), ModelGraphKind.Whole);
            _builder = new KeyFeatureBuilder(contract);
            _localRoot = new double[(Past + 1) * 3];
            _localRotations = new double[(Past + 1) * Joints * 4];
            Localizer.Localize(contract, _transition.KeyRootPositions, _transition.KeyLocalRotations, Past + 1, Past - 1, _localRoot, _localRotations);
            _features = new float[(Past + 1) * 9 * Joints];
        }

        /// <summary>The official SLERP baseline (root LERP + per-joint SLERP) for 30 frames × 22 joints.</summary>
        [Benchmark]
        public void Slerp() => _slerp.Inbetween(_transition);

        /// <summary>FK of 30 frames × 22 joints.</summary>
        [Benchmark]
        public void ForwardKinematics30() =>
            ForwardKinematics.Compute(_skeleton, Missing, _transition.RootPositions, _transition.LocalRotations, _positions, _rotations);

        /// <summary>6D decoding of 30 frames × 22 joints: baseline 6D + Δ → Gram–Schmidt → quaternion → hemisphere.</summary>
        [Benchmark]
        public double Decode6D()
        {
            double sum = 0;
            for (int i = 0; i < _baselines.Length; i++)
            {
                sum += OutputDecoder.Rotation(OutputDeltaMode.Slerp, _baselines[i], new ReadOnlySpan<float>(_deltas, 6 * i, 6)).W;
            }

            return sum;
        }

        /// <summary>Key features of 11 key frames (FK of each, 6D and positions relative to the reference key).</summary>
        [Benchmark]
        public void KeyFeatures() => _builder.Build(_localRoot, _localRotations, Past + 1, Past - 1, _features);

        private static QuaternionD RandomRotation(Random random)
        {
            var axis = new Vector3D(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            return Quaternions.FromAxisAngle((1.0 / axis.Length) * axis, 2 * random.NextDouble());
        }

        private static string Offsets(double[] o)
        {
            var rows = new string[o.Length / 3];
            for (int j = 0; j < rows.Length; j++)
            {
                rows[j] = FormattableString.Invariant($"[{o[3 * j]}, {o[3 * j + 1]}, {o[3 * j + 2]}]");
            }

            return string.Join(", ", rows);
        }

        private static ModelDescription Description(string meta)
        {
            var inputs = new[]
            {
                new TensorDescription(TensorNames.KeyFeatures, TensorElementKind.Float32, new long[] { 1, -1, 9 * Joints }),
                new TensorDescription(TensorNames.KeyFrameIndices, TensorElementKind.Int64, new long[] { -1 }),
                new TensorDescription(TensorNames.QueryFrameIndices, TensorElementKind.Int64, new long[] { -1 }),
                new TensorDescription(TensorNames.GapLength, TensorElementKind.Int64, new long[] { 1 }),
            };
            var outputs = new[]
            {
                new TensorDescription(TensorNames.RootPositionDelta, TensorElementKind.Float32, new long[] { 1, -1, 3 }),
                new TensorDescription(TensorNames.Rotation6DDelta, TensorElementKind.Float32, new long[] { 1, -1, Joints, 6 }),
                new TensorDescription(TensorNames.ContractVersion, TensorElementKind.Int64, new long[] { 1 }),
                new TensorDescription(TensorNames.JointCount, TensorElementKind.Int64, new long[] { 1 }),
                new TensorDescription(TensorNames.KeyFeatureSize, TensorElementKind.Int64, new long[] { 1 }),
            };
            return new ModelDescription("benchmark", inputs, outputs, new System.Collections.Generic.Dictionary<string, string> { ["deltainterp"] = meta });
        }
    }
}
