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
    /// <para>The whole and frame graphs of a model with contacts (contract version 3) also give <see cref="FootContacts"/>.</para>
    /// <para>With constants, the three constant outputs (contract version, joint count, key-feature size)
    /// are added to <see cref="Outputs"/>, for the load-time probe. Models with input Δ-mode <c>none</c>
    /// (a <c>query_features</c> input) are refused by <see cref="ModelChecks"/>, so no tensor is built for it.</para>
    /// <para>Allocates once at creation; nothing afterwards.</para>
    /// </remarks>
    public sealed class GraphTensors
    {
        private readonly InferenceTensor[] _inputs;
        private readonly InferenceTensor[] _outputs;

        private GraphTensors(ModelGraphKind graph, int pastFrames, int missingFrames, int queryFrames, InferenceTensor? keyFeatures, InferenceTensor? keyFrameIndices,
            InferenceTensor? queryFrameIndices, InferenceTensor gapLength, InferenceTensor? keyMemory, InferenceTensor? rootDelta, InferenceTensor? rotationDelta, InferenceTensor? footContacts, bool constants,
            int batch = 1, bool fill = true)
        {
            Graph = graph;
            Batch = batch;
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
            FootContacts = footContacts;
            var inputs = new List<InferenceTensor>(4);
            var outputs = new List<InferenceTensor>(5);
            switch (graph)
            {
                case ModelGraphKind.Whole:
                    inputs.AddRange(new[] { keyFeatures!, keyFrameIndices!, queryFrameIndices!, gapLength });
                    outputs.AddRange(new[] { rootDelta!, rotationDelta! });
                    if (footContacts != null) outputs.Add(footContacts);
                    break;
                case ModelGraphKind.Keys:
                    inputs.AddRange(new[] { keyFeatures!, keyFrameIndices!, gapLength });
                    outputs.Add(keyMemory!);
                    break;
                default:
                    inputs.AddRange(new[] { keyMemory!, queryFrameIndices!, gapLength });
                    outputs.AddRange(new[] { rootDelta!, rotationDelta! });
                    if (footContacts != null) outputs.Add(footContacts);
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
            if (!fill) return;
            for (int row = 0; row < batch; row++)
            {
                if (keyFrameIndices != null) SetKeyRow(row, missingFrames);
                gapLength.Longs![row] = missingFrames;
            }

            if (queryFrameIndices != null) SetQuery(0);
        }

        /// <summary>Rows (transitions) per run: 1, or the capacity of a batch (contract version 2).</summary>
        public int Batch { get; }

        /// <summary>Which graph these tensors are for.</summary>
        public ModelGraphKind Graph { get; }

        /// <summary>P, the number of past keys.</summary>
        public int PastFrames { get; }

        /// <summary>n, the gap length.</summary>
        public int MissingFrames { get; }

        /// <summary>N, the number of missing frames one run decodes (n for a whole transition, 1 for lazy frames); 0 for the keys graph.</summary>
        public int QueryFrameCount { get; }

        /// <summary>float32 [B, K, 9·J], K = P + 1 (B = 1 for version 1 graphs): filled by <see cref="KeyFeatureBuilder"/>; null for the frame graph.</summary>
        public InferenceTensor? KeyFeatures { get; }

        /// <summary>int64 [B, K] (version 1: [K]) = 0..P−1, P+n per row (filled at creation, <see cref="SetKeyRow"/>); null for the frame graph.</summary>
        public InferenceTensor? KeyFrameIndices { get; }

        /// <summary>int64 [B, N] (version 1: [N]), the missing frames wanted (<see cref="SetQuery"/>, <see cref="SetQueryRow"/>); null for the keys graph.</summary>
        public InferenceTensor? QueryFrameIndices { get; }

        /// <summary>int64 [B] (version 1: [1]) = n per row (filled at creation).</summary>
        public InferenceTensor GapLength { get; }

        /// <summary>float32 [B, R, 2, K, D] (version 1: [R, 2, K, D]): the keys graph's output and the frame graph's input (one array, no copy); null for the whole graph.</summary>
        public InferenceTensor? KeyMemory { get; }

        /// <summary>float32 [B, N, 3]; null for the keys graph.</summary>
        public InferenceTensor? RootPositionDelta { get; }

        /// <summary>float32 [B, N, J, 6]; null for the keys graph.</summary>
        public InferenceTensor? Rotation6DDelta { get; }

        /// <summary>float32 [B, N, 4], the predicted contact probabilities, when the model has them (<see cref="ModelContract.HasFootContacts"/>); else null, as for the keys graph.</summary>
        public InferenceTensor? FootContacts { get; }

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
        /// <param name="batch">Rows (transitions) per run; above 1 only for graphs with a batch axis (contract version 2).</param>
        public static GraphTensors Create(ModelContract contract, ModelGraphKind graph, int pastFrames, int missingFrames, int queryFrames, bool constants = false, int batch = 1)
        {
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            if (pastFrames < 1 || missingFrames < 1) throw new ArgumentException($"P = {pastFrames}, n = {missingFrames}; expected at least one past key and one missing frame");
            CheckBatch(contract, batch);
            bool b = contract.HasBatchAxis;
            int keys = pastFrames + 1;
            var features = InferenceTensor.Float(TensorNames.KeyFeatures, batch, keys, contract.KeyFeatureSize);
            var keyFrames = b ? InferenceTensor.Int64(TensorNames.KeyFrameIndices, batch, keys) : InferenceTensor.Int64(TensorNames.KeyFrameIndices, keys);
            var gap = InferenceTensor.Int64(TensorNames.GapLength, batch);
            switch (graph)
            {
                case ModelGraphKind.Whole:
                    if (queryFrames < 1 || queryFrames > missingFrames) throw new ArgumentOutOfRangeException(nameof(queryFrames), $"N = {queryFrames}; expected 1..{missingFrames}");
                    return new GraphTensors(graph, pastFrames, missingFrames, queryFrames, features, keyFrames, Query(contract, batch, queryFrames), gap,
                        null, RootDelta(batch, queryFrames), RotationDelta(contract, batch, queryFrames), Contacts(contract, batch, queryFrames), constants, batch);
                case ModelGraphKind.Keys:
                    ModelArchitecture a = contract.Architecture;
                    var memory = b ? InferenceTensor.Float(TensorNames.KeyMemory, batch, a.Blocks, 2, keys, a.Width) : InferenceTensor.Float(TensorNames.KeyMemory, a.Blocks, 2, keys, a.Width);
                    return new GraphTensors(graph, pastFrames, missingFrames, 0, features, keyFrames, null, gap, memory, null, null, null, constants, batch);
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
            int batch = keys.Batch;
            return new GraphTensors(ModelGraphKind.Frame, keys.PastFrames, keys.MissingFrames, queryFrames, null, null, Query(contract, batch, queryFrames),
                keys.GapLength, keys.KeyMemory, RootDelta(batch, queryFrames), RotationDelta(contract, batch, queryFrames), Contacts(contract, batch, queryFrames), constants, batch);
        }

        /// <summary>
        /// Tensors for the frame graph of <paramref name="batch"/> rows whose <c>key_memory</c> stays on an engine's
        /// device (<see cref="IDeviceTensorBackend.BindOnDevice"/>): <see cref="KeyMemory"/> names and shapes that
        /// input only (a view of <paramref name="keys"/>' array, never read or written); gap lengths, query frames
        /// and outputs are this set's own. Gap lengths are placeholders until each row's is written (<see cref="SetKeyRow"/>).
        /// </summary>
        public static GraphTensors ForDeviceFrame(ModelContract contract, GraphTensors keys, int batch, int queryFrames)
        {
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            if (keys == null || keys.Graph != ModelGraphKind.Keys) throw new ArgumentException("expected the keys graph's tensors", nameof(keys));
            if (batch < 1 || batch > keys.Batch) throw new ArgumentOutOfRangeException(nameof(batch), batch, $"expected 1..{keys.Batch} rows");
            if (queryFrames < 1) throw new ArgumentOutOfRangeException(nameof(queryFrames), queryFrames, "expected at least one query frame");
            InferenceTensor memory = batch == keys.Batch ? keys.KeyMemory! : keys.KeyMemory!.Prefix(batch);
            return new GraphTensors(ModelGraphKind.Frame, keys.PastFrames, queryFrames, queryFrames, null, null, Query(contract, batch, queryFrames),
                InferenceTensor.Int64(TensorNames.GapLength, batch), memory, RootDelta(batch, queryFrames), RotationDelta(contract, batch, queryFrames), Contacts(contract, batch, queryFrames), false, batch);
        }

        /// <summary>
        /// The same tensors for the first <paramref name="rows"/> rows only (views over the same arrays, no
        /// copy): a batch of fewer transitions than the capacity. Version 2 graphs only.
        /// </summary>
        public GraphTensors Prefix(int rows)
        {
            if (rows < 1 || rows > Batch) throw new ArgumentOutOfRangeException(nameof(rows), rows, $"expected 1..{Batch} rows");
            if (rows == Batch) return this;
            if (ContractVersion != null) throw new InvalidOperationException("constant outputs are for the probe run only");
            return new GraphTensors(Graph, PastFrames, MissingFrames, QueryFrameCount, KeyFeatures?.Prefix(rows), KeyFrameIndices?.Prefix(rows), QueryFrameIndices?.Prefix(rows),
                GapLength.Prefix(rows), KeyMemory?.Prefix(rows), RootPositionDelta?.Prefix(rows), Rotation6DDelta?.Prefix(rows), FootContacts?.Prefix(rows), false, rows, fill: false);
        }

        /// <summary>Writes row <paramref name="row"/>'s key frame indices 0..P−1, P+n and its gap length n (rows of one batch may differ in n).</summary>
        public void SetKeyRow(int row, int missingFrames)
        {
            if ((uint)row >= (uint)Batch) throw new ArgumentOutOfRangeException(nameof(row));
            int keys = PastFrames + 1;
            long[]? k = KeyFrameIndices?.Longs;
            if (k != null)
            {
                int o = row * keys;
                for (int i = 0; i < PastFrames; i++) k[o + i] = i;
                k[o + PastFrames] = PastFrames + missingFrames;
            }

            GapLength.Longs![row] = missingFrames;
        }

        /// <summary>Row <paramref name="row"/> asks for missing frames <paramref name="firstMissing"/>, +1, … of its own gap.</summary>
        public void SetQueryRow(int row, int firstMissing)
        {
            long[] query = QueryFrameIndices?.Longs ?? throw new InvalidOperationException("the keys graph has no query frames");
            if ((uint)row >= (uint)Batch) throw new ArgumentOutOfRangeException(nameof(row));
            int o = row * QueryFrameCount;
            for (int i = 0; i < QueryFrameCount; i++) query[o + i] = PastFrames + firstMissing + i;
        }

        /// <summary>Binds these tensors to <paramref name="backend"/> once (<see cref="IInferenceBackend.Bind"/>).</summary>
        public IInferenceBinding Bind(IInferenceBackend backend)
        {
            if (backend == null) throw new ArgumentNullException(nameof(backend));
            return backend.Bind(_inputs, _outputs);
        }

        /// <summary>
        /// Binds these tensors to <paramref name="backend"/> once with the tensor named <paramref name="onDevice"/>
        /// kept on its device (<see cref="IDeviceTensorBackend.BindOnDevice"/>).
        /// </summary>
        public IDeviceTensorBinding BindOnDevice(IDeviceTensorBackend backend, string onDevice)
        {
            if (backend == null) throw new ArgumentNullException(nameof(backend));
            return backend.BindOnDevice(_inputs, _outputs, onDevice);
        }

        /// <summary>
        /// Asks for missing frames <paramref name="firstMissing"/>, +1, … (0-based within the gap): writes
        /// P + firstMissing + i into <see cref="QueryFrameIndices"/>.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">The frames run past the gap.</exception>
        public void SetQuery(int firstMissing)
        {
            long[] query = QueryFrameIndices?.Longs ?? throw new InvalidOperationException("the keys graph has no query frames");
            int n = QueryFrameCount;
            if (firstMissing < 0 || firstMissing + n > MissingFrames)
            {
                throw new ArgumentOutOfRangeException(nameof(firstMissing), $"missing frames {firstMissing}..{firstMissing + n - 1}; expected 0..{MissingFrames - 1}");
            }

            for (int row = 0; row < Batch; row++)
            {
                for (int i = 0; i < n; i++) query[row * n + i] = PastFrames + firstMissing + i;
            }
        }

        private static void CheckBatch(ModelContract contract, int batch)
        {
            if (batch < 1) throw new ArgumentOutOfRangeException(nameof(batch), batch, "expected at least one row");
            if (batch > 1 && !contract.HasBatchAxis)
            {
                throw new ArgumentException($"{contract.Source} has contract version {contract.ContractVersion}, without a batch axis; export it again (python3 -m deltainterp export) to run transitions in batches", nameof(batch));
            }
        }

        private static InferenceTensor Query(ModelContract contract, int batch, int queryFrames) =>
            contract.HasBatchAxis ? InferenceTensor.Int64(TensorNames.QueryFrameIndices, batch, queryFrames) : InferenceTensor.Int64(TensorNames.QueryFrameIndices, queryFrames);

        private static InferenceTensor RootDelta(int batch, int queryFrames) => InferenceTensor.Float(TensorNames.RootPositionDelta, batch, queryFrames, 3);

        private static InferenceTensor? Contacts(ModelContract contract, int batch, int queryFrames) =>
            contract.HasFootContacts ? InferenceTensor.Float(TensorNames.FootContacts, batch, queryFrames, ModelContract.ContactChannelCount) : null;

        private static InferenceTensor RotationDelta(ModelContract contract, int batch, int queryFrames) => InferenceTensor.Float(TensorNames.Rotation6DDelta, batch, queryFrames, contract.JointCount, 6);
    }
}
