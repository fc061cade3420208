using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The Δ-Interpolator pipeline on any <see cref="IInferenceBackend"/>: a <see cref="Transition"/>
    /// (P past keys, a target key, n missing frames, world space, data units) → <see cref="Localizer"/> →
    /// input builders → network → <see cref="DeltaBaseline"/> + deltas → <see cref="OutputDecoder"/> →
    /// un-localize → the missing frames' root positions and local rotations (and FK positions on request).
    /// The benchmark, the CLI and the Unity component all go through this one class.
    /// </summary>
    /// <remarks>
    /// <para>Buffers and backend bindings are created once per request shape (P, n) and reused: after the
    /// first call of a shape, <see cref="Inbetween(Transition)"/> allocates nothing.</para>
    /// <para>Not thread-safe: use one instance per thread (each owns its backends). Dispose it to release
    /// the backends it was given.</para>
    /// </remarks>
    public sealed class Inbetweener : IInbetweener, IDisposable
    {
        private readonly IInferenceBackend _whole;
        private readonly IInferenceBackend? _keys;
        private readonly IInferenceBackend? _frame;
        private readonly RowDecoder _rows;
        private readonly ShapeCache<Workspace> _workspaces = new ShapeCache<Workspace>();
        private readonly ShapeCache<LazyInbetweener> _lazy = new ShapeCache<LazyInbetweener>();
        private Skeleton? _checkedSkeleton;
        private Workspace? _last;
        private bool _disposed;

        /// <summary>
        /// Checks the contract of every graph (metadata, tensor names, constant outputs from one probe run)
        /// and takes ownership of the backends.
        /// </summary>
        /// <param name="whole">The whole-transition graph (<c>NAME.onnx</c>).</param>
        /// <param name="keys">The lazy keys graph (<c>NAME.keys.onnx</c>), or null.</param>
        /// <param name="frame">The lazy frame graph (<c>NAME.frame.onnx</c>), or null; needed with <paramref name="keys"/>.</param>
        /// <exception cref="ModelContractException">A graph does not fit the contract; the message says what to do.</exception>
        public Inbetweener(IInferenceBackend whole, IInferenceBackend? keys = null, IInferenceBackend? frame = null)
        {
            _whole = whole ?? throw new ArgumentNullException(nameof(whole));
            try
            {
                Contract = ModelContract.Read(whole.Description, ModelGraphKind.Whole);
                if ((keys == null) != (frame == null))
                {
                    throw new ArgumentException("lazy decoding needs both the keys and the frame graph (or neither)");
                }

                if (keys != null && frame != null)
                {
                    KeysContract = ModelContract.Read(keys.Description, ModelGraphKind.Keys);
                    FrameContract = ModelContract.Read(frame.Description, ModelGraphKind.Frame);
                    Contract.CheckSameExport(KeysContract);
                    Contract.CheckSameExport(FrameContract);
                    _keys = keys;
                    _frame = frame;
                }

                _rows = new RowDecoder(Contract);
                Probe();
            }
            catch
            {
                whole.Dispose();
                keys?.Dispose();
                frame?.Dispose();
                throw;
            }
        }

        /// <summary>The whole graph's contract (skeleton, unit scale, delta mode, architecture).</summary>
        public ModelContract Contract { get; }

        /// <summary>The keys graph's contract, or null without lazy graphs.</summary>
        public ModelContract? KeysContract { get; }

        /// <summary>The frame graph's contract, or null without lazy graphs.</summary>
        public ModelContract? FrameContract { get; }

        /// <summary>True when the lazy graphs were given: <see cref="CreateLazy"/> works.</summary>
        public bool SupportsLazyDecoding => _keys != null;

        /// <inheritdoc />
        public string Id { get; set; } = "model";

        /// <inheritdoc />
        public string DisplayName { get; set; } = "Δ-Interp.";

        /// <summary>The <c>key_features</c> fed by the last whole-transition call (K × 9J), for diagnostics and parity tests.</summary>
        internal ReadOnlySpan<float> LastKeyFeatures => _last == null ? default : _last.Tensors.KeyFeatures!.Floats;

        /// <summary>The raw <c>root_position_delta</c> of the last whole-transition call (n × 3).</summary>
        internal ReadOnlySpan<float> LastRootPositionDelta => _last == null ? default : _last.Tensors.RootPositionDelta!.Floats;

        /// <summary>The raw <c>rotation_6d_delta</c> of the last whole-transition call (n × J × 6).</summary>
        internal ReadOnlySpan<float> LastRotation6DDelta => _last == null ? default : _last.Tensors.Rotation6DDelta!.Floats;

        /// <summary>The localization of the last whole-transition call.</summary>
        internal Localization LastLocalization { get; private set; }

        /// <summary>
        /// Fills every missing frame of <paramref name="transition"/> in one network run.
        /// </summary>
        /// <exception cref="ModelContractException">The transition's skeleton is not the model's.</exception>
        /// <exception cref="ArgumentException">P + n exceeds the model's largest frame index.</exception>
        public void Inbetween(Transition transition)
        {
            Workspace w = Prepare(transition);
            w.Binding.Run();
            _last = w;
            LastLocalization = w.Keys.Localization;
            for (int k = 0; k < transition.MissingFrames; k++)
            {
                DecodeFrame(transition, w, k, k);
            }
        }

        /// <summary>
        /// <see cref="Inbetween(Transition)"/>, then FK of the missing frames with the transition's
        /// skeleton (world, data units) into <paramref name="globalPositions"/> (n × J × 3).
        /// </summary>
        public void Inbetween(Transition transition, Span<double> globalPositions)
        {
            Inbetween(transition);
            Workspace w = _last!;
            ForwardKinematics.Compute(transition.Skeleton, transition.MissingFrames, transition.RootPositions, transition.LocalRotations, globalPositions, w.GlobalRotations);
        }

        /// <summary>
        /// A reusable lazy decoder for transitions of P past keys and n missing frames: it encodes the
        /// keys once per transition (<see cref="LazyInbetweener.Begin"/>) and decodes frames one at a time
        /// (<see cref="LazyInbetweener.DecodeFrame"/>), each costing a fraction of a whole transition.
        /// Owned by this inbetweener (disposed with it): create one per shape and reuse it for every
        /// transition of that shape, since each holds its own buffers and backend bindings until
        /// <see cref="Dispose"/>.
        /// </summary>
        /// <exception cref="InvalidOperationException">The lazy graphs were not loaded.</exception>
        public LazyInbetweener CreateLazy(int pastFrames, int missingFrames)
        {
            ThrowIfDisposed();
            if (_keys == null || _frame == null)
            {
                throw new InvalidOperationException($"{Contract.Source} was loaded without its .keys.onnx and .frame.onnx graphs; export them (python3 -m deltainterp export writes all three) and load them beside the whole graph");
            }

            CheckLength(pastFrames, missingFrames);
            var lazy = new LazyInbetweener(this, _keys, _frame, pastFrames, missingFrames);
            // Held to release its bindings with the model's; each caller gets its own (it keeps its transition).
            _lazy.Add(pastFrames, missingFrames, lazy);
            return lazy;
        }

        /// <summary>Releases the bindings and the backends.</summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            for (int i = 0; i < _lazy.Count; i++) _lazy[i].DisposeBindings();
            for (int i = 0; i < _workspaces.Count; i++) _workspaces[i].Binding.Dispose();
            _lazy.Clear();
            _workspaces.Clear();
            _whole.Dispose();
            _keys?.Dispose();
            _frame?.Dispose();
        }

        /// <summary>The keys graph (lazy decoding), or null: the schedulers bind it for their batched runs.</summary>
        public IInferenceBackend? KeysBackend => _keys;

        /// <summary>The frame graph (lazy decoding), or null.</summary>
        public IInferenceBackend? FrameBackend => _frame;

        internal void CheckSkeleton(Skeleton skeleton)
        {
            if (ReferenceEquals(skeleton, _checkedSkeleton)) return;
            Contract.CheckSkeleton(skeleton, "the transition's skeleton");
            _checkedSkeleton = skeleton;
        }

        internal void CheckLength(int pastFrames, int missingFrames)
        {
            // Only errors refuse a request; training-range warnings are for tools and the inspector
            // (ModelChecks.Request), since a game may ask for longer gaps on purpose.
            var report = new ModelCheckReport();
            ModelChecks.Request(Contract, pastFrames, missingFrames, report);
            ModelCheck? error = report.FirstError;
            if (error != null) throw new ArgumentException(error.Message + "; " + error.Remedy);
        }

        private void DecodeFrame(Transition t, Workspace w, int row, int k)
        {
            _rows.Decode(t, w.Keys, OutputRow.Of(w.Tensors, row, Contract.JointCount), k, t.RootPositions, t.LocalRotations);
        }

        private Workspace Prepare(Transition t)
        {
            ThrowIfDisposed();
            if (t == null) throw new ArgumentNullException(nameof(t));
            CheckSkeleton(t.Skeleton);
            Workspace? w = _workspaces.Find(t.PastFrames, t.MissingFrames);
            if (w == null)
            {
                CheckLength(t.PastFrames, t.MissingFrames);
                w = _workspaces.Add(t.PastFrames, t.MissingFrames, new Workspace(this, _whole, t.PastFrames, t.MissingFrames));
            }

            _rows.Localize(t, w.Keys, w.Tensors.KeyFeatures!.Floats);
            return w;
        }

        private void Probe()
        {
            // One run per graph on a neutral request of the smallest shape: reads the constant outputs
            // (which the metadata cannot prove) and warms the engine up.
            GraphTensors whole = GraphTensors.Create(Contract, ModelGraphKind.Whole, 1, 1, 1, constants: true);
            RunProbe(_whole, whole, Contract);
            if (_keys != null && _frame != null)
            {
                GraphTensors keys = GraphTensors.Create(Contract, ModelGraphKind.Keys, 1, 1, 0, constants: true);
                RunProbe(_keys, keys, KeysContract!);
                RunProbe(_frame, GraphTensors.ForFrame(Contract, keys, 1, constants: true), FrameContract!);
            }
        }

        private static void RunProbe(IInferenceBackend backend, GraphTensors tensors, ModelContract contract)
        {
            using (IInferenceBinding binding = tensors.Bind(backend))
            {
                try
                {
                    binding.Run();
                }
                catch (InvalidOperationException e)
                {
                    throw new ModelContractException(contract.Source, "a probe run with the contract's input shapes failed (" + e.Message + ")",
                        "expected a graph that accepts the inputs of Documentation~/model-contract.md; export the checkpoint again");
                }
            }

            contract.CheckConstants(tensors.ContractVersion!.Longs![0], tensors.JointCount!.Longs![0], tensors.KeyFeatureSize!.Longs![0]);
            if (tensors.FootContacts != null)
            {
                var report = new ModelCheckReport();
                ModelChecks.ContactProbabilities(contract, tensors.FootContacts.Floats, report);
                report.ThrowIfErrors();
            }
        }

        private void ThrowIfDisposed()
        {
            if (_disposed) throw new ObjectDisposedException(nameof(Inbetweener));
        }

        /// <summary>Buffers, tensors and binding of one request shape.</summary>
        private sealed class Workspace : IDisposable
        {
            public Workspace(Inbetweener owner, IInferenceBackend backend, int pastFrames, int missingFrames)
            {
                int jc = owner.Contract.JointCount;
                Keys = new LocalizedKeys(owner.Contract, pastFrames);
                GlobalRotations = new double[missingFrames * jc * 4];
                Tensors = GraphTensors.Create(owner.Contract, ModelGraphKind.Whole, pastFrames, missingFrames, missingFrames);
                Binding = Tensors.Bind(backend);
            }

            public LocalizedKeys Keys { get; }
            public double[] GlobalRotations { get; }
            public GraphTensors Tensors { get; }
            public IInferenceBinding Binding { get; }

            public void Dispose() => Binding.Dispose();
        }
    }
}
