using System;
using DeltaInterpolator.Core.Inbetweening;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Lazy decoding of transitions of one shape (P past keys, n missing frames): <see cref="Begin"/> runs
    /// the keys graph once (key tokens never attend to missing frames, so their encoding is final), then
    /// each <see cref="DecodeFrame"/> runs the small frame graph for one missing frame. Use it when a game
    /// wants the first frame now and the rest one per rendered frame. The frames equal those of
    /// <see cref="Inbetweener.Inbetween(Transition)"/> to float rounding (tested to 1e-5).
    /// </summary>
    /// <remarks>Created by <see cref="Inbetweener.CreateLazy"/>; reusable for any number of transitions of
    /// its shape; allocation-free after creation; not thread-safe.</remarks>
    public sealed class LazyInbetweener
    {
        private readonly Inbetweener _owner;
        private readonly LocalizedKeys _localized;
        private readonly RowDecoder _rows;
        private readonly GraphTensors _keys;
        private readonly GraphTensors _frame;
        private readonly IInferenceBinding _keysBinding;
        private readonly IInferenceBinding _frameBinding;
        private Transition? _transition;

        internal LazyInbetweener(Inbetweener owner, IInferenceBackend keys, IInferenceBackend frame, int pastFrames, int missingFrames)
        {
            _owner = owner;
            ModelContract c = owner.Contract;
            PastFrames = pastFrames;
            MissingFrames = missingFrames;
            _localized = new LocalizedKeys(c, pastFrames);
            _rows = new RowDecoder(c);
            _keys = GraphTensors.Create(c, ModelGraphKind.Keys, pastFrames, missingFrames, 0);
            _frame = GraphTensors.ForFrame(c, _keys, 1);
            KeyMemory = _keys.KeyMemory!;
            // The same key_memory array is the keys graph's output and the frame graph's input: no copy.
            _keysBinding = _keys.Bind(keys);
            try
            {
                _frameBinding = _frame.Bind(frame);
            }
            catch
            {
                _keysBinding.Dispose();
                throw;
            }
        }

        /// <summary>Number of past keys P this decoder was made for.</summary>
        public int PastFrames { get; }

        /// <summary>Number of missing frames n this decoder was made for.</summary>
        public int MissingFrames { get; }

        /// <summary>The cached key encoding of the current transition, [R, 2, K, D].</summary>
        public InferenceTensor KeyMemory { get; }

        /// <summary>
        /// Encodes the keys of <paramref name="transition"/> (runs the keys graph once). The transition is
        /// kept until the next <see cref="Begin"/>: <see cref="DecodeFrame"/> writes into its output buffers.
        /// </summary>
        /// <exception cref="ArgumentException">The transition's shape is not this decoder's.</exception>
        public void Begin(Transition transition)
        {
            if (transition == null) throw new ArgumentNullException(nameof(transition));
            if (transition.PastFrames != PastFrames || transition.MissingFrames != MissingFrames)
            {
                throw new ArgumentException($"the transition has P = {transition.PastFrames}, n = {transition.MissingFrames} but this lazy decoder was created for P = {PastFrames}, n = {MissingFrames}; create one per shape with Inbetweener.CreateLazy");
            }

            _owner.CheckSkeleton(transition.Skeleton);
            _rows.Localize(transition, _localized, _keys.KeyFeatures!.Floats);
            _keysBinding.Run();
            _transition = transition;
        }

        /// <summary>
        /// Decodes missing frame <paramref name="k"/> (0-based, 0..n−1) into the transition's
        /// <see cref="Transition.RootPositions"/> and <see cref="Transition.LocalRotations"/> at k.
        /// </summary>
        /// <exception cref="InvalidOperationException"><see cref="Begin"/> was not called.</exception>
        public void DecodeFrame(int k)
        {
            Transition t = _transition ?? throw new InvalidOperationException("call Begin(transition) before DecodeFrame");
            if ((uint)k >= (uint)MissingFrames) throw new ArgumentOutOfRangeException(nameof(k), $"missing frame {k}; expected 0..{MissingFrames - 1}");
            _frame.SetQuery(k);
            _frameBinding.Run();
            _rows.Decode(t, _localized, OutputRow.Of(_frame, 0, _owner.Contract.JointCount), k, t.RootPositions, t.LocalRotations);
        }

        internal void DisposeBindings()
        {
            _keysBinding.Dispose();
            _frameBinding.Dispose();
        }
    }
}
