using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The tensors of one exported graph for one request shape (P past keys, a gap of n frames, N query
    /// frames), named and shaped as Documentation~/model-contract.md says, with the integer inputs filled.
    /// The one place that knows which graph takes and gives which tensors: whole and lazy decoding, the
    /// load-time probe, the speed harness and every backend get their tensors here.
    /// </summary>
    /// <remarks>
    /// <para>Which tensors exist depends on <see cref="Graph"/>:</para>
    /// <list type="table">
    /// <item><term>whole</term><description><see cref="KeyFeatures"/>, <see cref="KeyFrameIndices"/>,
    /// <see cref="QueryFrameIndices"/>, <see cref="GapLength"/> → <see cref="RootPositionDelta"/>, <see cref="Rotation6DDelta"/></description></item>
    /// <item><term>keys</term><description><see cref="KeyFeatures"/>, <see cref="KeyFrameIndices"/>,
    /// <see cref="GapLength"/> → <see cref="KeyMemory"/></description></item>
    /// <item><term>frame</term><description><see cref="KeyMemory"/>, <see cref="QueryFrameIndices"/>,
    /// <see cref="GapLength"/> → <see cref="RootPositionDelta"/>, <see cref="Rotation6DDelta"/></description></item>
    /// </list>
    /// <para>With constants, the three constant outputs (contract version, joint count, key-feature size)
    /// are added to <see cref="Outputs"/>, for the load-time probe. Models with input Δ-mode <c>none</c>
    /// (a <c>query_features</c> input) are refused by <see cref="ModelChecks"/>, so no tensor is built for it.</para>
    /// <para>Allocates once at creation; nothing afterwards.</para>
    /// </remarks>
    internal sealed class GraphTensors
    {
        private readonly InferenceTensor[] _inputs;
        private readonly InferenceTensor[] _outputs;

        private GraphTensors(ModelGraphKind graph, int pastFrames, int missingFrames, int queryFrames, InferenceTensor? keyFeatures, InferenceTensor? keyFrameIndices,
            InferenceTensor? queryFrameIndices, InferenceTensor gapLength, InferenceTensor? keyMemory, InferenceTensor? rootDelta, InferenceTensor? rotationDelta, bool constants)
        {
            Graph = graph;
            PastFrames = pastFrames;
            MissingFrames = missingFrames;
            QueryFrameCount = queryFrames;
            KeyFeatures = keyFeatures;
            KeyFrameIndices = keyFrameIndices;
            QueryFrameIndices = queryFrameIndices;
            GapLength = gapLength;
            KeyMemory = keyMemory;
            RootPositionDelta = rootDelta;
            Rotation6DDelta = rotationDelta;
            var inputs = new List<InferenceTensor>(4);
            var outputs = new List<InferenceTensor>(5);
            switch (graph)
            {
                case ModelGraphKind.Whole:
                    inputs.AddRange(new[] { keyFeatures!, keyFrameIndices!, queryFrameIndices!, gapLength });
                    outputs.AddRange(new[] { rootDelta!, rotationDelta! });
                    break;
                case ModelGraphKind.Keys:
                    inputs.AddRange(new[] { keyFeatures!, keyFrameIndices!, gapLength });
                    outputs.Add(keyMemory!);
                    break;
                default:
                    inputs.AddRange(new[] { keyMemory!, queryFrameIndices!, gapLength });
                    outputs.AddRange(new[] { rootDelta!, rotationDelta! });
                    break;
            }

            if (constants)
            {
                ContractVersion = InferenceTensor.Int64(TensorNames.ContractVersion, 1);
                JointCount = InferenceTensor.Int64(TensorNames.JointCount, 1);
                KeyFeatureSize = InferenceTensor.Int64(TensorNames.KeyFeatureSize, 1);
                outputs.AddRange(new[] { ContractVersion, JointCount, KeyFeatureSize });
            }

            _inputs = inputs.ToArray();
            _outputs = outputs.ToArray();
            if (keyFrameIndices != null) WriteKeyFrames(pastFrames, missingFrames, keyFrameIndices.Longs);
            gapLength.Longs![0] = missingFrames;
            if (queryFrameIndices != null) SetQuery(0);
        }

        /// <summary>Which graph these tensors are for.</summary>
        public ModelGraphKind Graph { get; }

        /// <summary>P, the number of past keys.</summary>
        public int PastFrames { get; }

        /// <summary>n, the gap length.</summary>
        public int MissingFrames { get; }

        /// <summary>N, the number of missing frames one run decodes (n for a whole transition, 1 for lazy frames); 0 for the keys graph.</summary>
        public int QueryFrameCount { get; }

        /// <summary>float32 [1, K, 9·J], K = P + 1: filled by <see cref="KeyFeatureBuilder"/>; null for the frame graph.</summary>
        public InferenceTensor? KeyFeatures { get; }

        /// <summary>int64 [K] = 0..P−1, P+n (filled at creation); null for the frame graph.</summary>
        public InferenceTensor? KeyFrameIndices { get; }

        /// <summary>int64 [N], the missing frames wanted (<see cref="SetQuery"/>); null for the keys graph.</summary>
        public InferenceTensor? QueryFrameIndices { get; }

        /// <summary>int64 [1] = n (filled at creation).</summary>
        public InferenceTensor GapLength { get; }

        /// <summary>float32 [R, 2, K, D]: the keys graph's output and the frame graph's input (one array, no copy); null for the whole graph.</summary>
        public InferenceTensor? KeyMemory { get; }

        /// <summary>float32 [1, N, 3]; null for the keys graph.</summary>
        public InferenceTensor? RootPositionDelta { get; }

        /// <summary>float32 [1, N, J, 6]; null for the keys graph.</summary>
        public InferenceTensor? Rotation6DDelta { get; }

        /// <summary>Constant output int64 [1], when created with constants.</summary>
        public InferenceTensor? ContractVersion { get; }

        /// <summary>Constant output int64 [1], when created with constants.</summary>
        public InferenceTensor? JointCount { get; }

        /// <summary>Constant output int64 [1], when created with constants.</summary>
        public InferenceTensor? KeyFeatureSize { get; }

        /// <summary>The graph's inputs, in the contract's order.</summary>
        public IReadOnlyList<InferenceTensor> Inputs => _inputs;

        /// <summary>The outputs wanted, in the contract's order (constants last).</summary>
        public IReadOnlyList<InferenceTensor> Outputs => _outputs;

        /// <summary>
        /// Tensors for the whole graph (<paramref name="queryFrames"/> = n decodes the whole gap) or the keys
        /// graph (<paramref name="queryFrames"/> ignored).
        /// </summary>
        /// <param name="contract">The model's contract (joint count, architecture).</param>
        /// <param name="graph"><see cref="ModelGraphKind.Whole"/> or <see cref="ModelGraphKind.Keys"/>; use <see cref="ForFrame"/> for the frame graph.</param>
        /// <param name="pastFrames">P ≥ 1.</param>
        /// <param name="missingFrames">n ≥ 1.</param>
        /// <param name="queryFrames">N, frames per run of the whole graph (1..n).</param>
        /// <param name="constants">Also bind the constant outputs (the load-time probe).</param>
        public static GraphTensors Create(ModelContract contract, ModelGraphKind graph, int pastFrames, int missingFrames, int queryFrames, bool constants = false)
        {
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            if (pastFrames < 1 || missingFrames < 1) throw new ArgumentException($"P = {pastFrames}, n = {missingFrames}; expected at least one past key and one missing frame");
            int keys = pastFrames + 1;
            var features = InferenceTensor.Float(TensorNames.KeyFeatures, 1, keys, contract.KeyFeatureSize);
            var keyFrames = InferenceTensor.Int64(TensorNames.KeyFrameIndices, keys);
            var gap = InferenceTensor.Int64(TensorNames.GapLength, 1);
            switch (graph)
            {
                case ModelGraphKind.Whole:
                    if (queryFrames < 1 || queryFrames > missingFrames) throw new ArgumentOutOfRangeException(nameof(queryFrames), $"N = {queryFrames}; expected 1..{missingFrames}");
                    return new GraphTensors(graph, pastFrames, missingFrames, queryFrames, features, keyFrames, InferenceTensor.Int64(TensorNames.QueryFrameIndices, queryFrames), gap,
                        null, RootDelta(queryFrames), RotationDelta(contract, queryFrames), constants);
                case ModelGraphKind.Keys:
                    ModelArchitecture a = contract.Architecture;
                    var memory = InferenceTensor.Float(TensorNames.KeyMemory, a.Blocks, 2, keys, a.Width);
                    return new GraphTensors(graph, pastFrames, missingFrames, 0, features, keyFrames, null, gap, memory, null, null, constants);
                default:
                    throw new ArgumentException("the frame graph's tensors share the keys graph's key_memory and gap_length: use GraphTensors.ForFrame(keys, …)", nameof(graph));
            }
        }

        /// <summary>
        /// Tensors for the frame graph that decodes <paramref name="queryFrames"/> missing frames per run from
        /// the key memory of <paramref name="keys"/>: <see cref="KeyMemory"/> and <see cref="GapLength"/> are
        /// the same tensors, so the keys graph's output is the frame graph's input without a copy.
        /// </summary>
        public static GraphTensors ForFrame(ModelContract contract, GraphTensors keys, int queryFrames, bool constants = false)
        {
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            if (keys == null || keys.Graph != ModelGraphKind.Keys) throw new ArgumentException("expected the keys graph's tensors", nameof(keys));
            if (queryFrames < 1 || queryFrames > keys.MissingFrames) throw new ArgumentOutOfRangeException(nameof(queryFrames), $"N = {queryFrames}; expected 1..{keys.MissingFrames}");
            return new GraphTensors(ModelGraphKind.Frame, keys.PastFrames, keys.MissingFrames, queryFrames, null, null, InferenceTensor.Int64(TensorNames.QueryFrameIndices, queryFrames),
                keys.GapLength, keys.KeyMemory, RootDelta(queryFrames), RotationDelta(contract, queryFrames), constants);
        }

        /// <summary>Binds these tensors to <paramref name="backend"/> once (<see cref="IInferenceBackend.Bind"/>).</summary>
        public IInferenceBinding Bind(IInferenceBackend backend)
        {
            if (backend == null) throw new ArgumentNullException(nameof(backend));
            return backend.Bind(_inputs, _outputs);
        }

        /// <summary>
        /// Asks for missing frames <paramref name="firstMissing"/>, +1, … (0-based within the gap): writes
        /// P + firstMissing + i into <see cref="QueryFrameIndices"/>.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">The frames run past the gap.</exception>
        public void SetQuery(int firstMissing)
        {
            long[] query = QueryFrameIndices?.Longs ?? throw new InvalidOperationException("the keys graph has no query frames");
            if (firstMissing < 0 || firstMissing + query.Length > MissingFrames)
            {
                throw new ArgumentOutOfRangeException(nameof(firstMissing), $"missing frames {firstMissing}..{firstMissing + query.Length - 1}; expected 0..{MissingFrames - 1}");
            }

            for (int i = 0; i < query.Length; i++) query[i] = PastFrames + firstMissing + i;
        }

        /// <summary>Writes 0..P−1 then P+n (relative to the first past key; ≤ <see cref="ModelContract.LargestFrameIndex"/>).</summary>
        private static void WriteKeyFrames(int pastFrames, int missingFrames, long[]? keyFrameIndices)
        {
            for (int i = 0; i < pastFrames; i++) keyFrameIndices![i] = i;
            keyFrameIndices![pastFrames] = pastFrames + missingFrames;
        }

        private static InferenceTensor RootDelta(int queryFrames) => InferenceTensor.Float(TensorNames.RootPositionDelta, 1, queryFrames, 3);

        private static InferenceTensor RotationDelta(ModelContract contract, int queryFrames) => InferenceTensor.Float(TensorNames.Rotation6DDelta, 1, queryFrames, contract.JointCount, 6);
    }
}
