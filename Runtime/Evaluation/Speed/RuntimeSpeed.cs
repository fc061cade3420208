using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Kinematics;

namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>
    /// How long the runtime takes per request, measured carefully (<see cref="Timing.Measure"/>): the whole
    /// pipeline and the network alone at each of <see cref="Lengths"/>, lazy decoding, SLERP + FK, and the
    /// managed allocation per transition. Any backend: the caller loads the model and opens the bare network.
    /// </summary>
    public static class RuntimeSpeed
    {
        /// <summary>Past key frames of every timed request (the benchmark's context).</summary>
        public const int PastFrames = 10;

        /// <summary>The transition length of the lazy, SLERP + FK and allocation measurements.</summary>
        public const int LazyLength = 30;

        private static readonly int[] LengthList = { 5, 15, LazyLength };

        /// <summary>The transition lengths (missing frames) timed, in order.</summary>
        public static IReadOnlyList<int> Lengths => LengthList;

        /// <summary>Measures everything; takes seconds to minutes.</summary>
        /// <param name="model">The loaded model.</param>
        /// <param name="openNetwork">Opens a second session of the model's whole graph, timed without the C# around it.</param>
        /// <param name="repeats">Timed repetitions per measurement (four times as many for SLERP + FK).</param>
        public static SpeedResults Measure(Inbetweener model, Func<IInferenceBackend> openNetwork, int repeats)
        {
            ModelContract contract = model.Contract;
            var transition = new Timing[LengthList.Length];
            var network = new Timing[LengthList.Length];
            for (int i = 0; i < LengthList.Length; i++)
            {
                int n = LengthList[i];
                Transition t = SyntheticTransition.Create(contract, PastFrames, n);
                var global = new double[n * contract.JointCount * 3];
                transition[i] = Timing.Measure(() => model.Inbetween(t, global), repeats, 1e3);
                network[i] = MeasureNetwork(openNetwork, contract, n, repeats);
            }

            Timing? lazyKeys = null, lazyFrame = null;
            if (model.SupportsLazyDecoding)
            {
                Transition t = SyntheticTransition.Create(contract, PastFrames, LazyLength);
                LazyInbetweener lazy = model.CreateLazy(PastFrames, LazyLength);
                lazyKeys = Timing.Measure(() => lazy.Begin(t), repeats, 1e3);
                int k = 0;
                lazyFrame = Timing.Measure(() => lazy.DecodeFrame(k = (k + 1) % LazyLength), repeats, 1e3);
            }

            Timing slerpFk;
            {
                Transition t = SyntheticTransition.Create(contract, PastFrames, LazyLength);
                var slerp = new SlerpBaseline();
                var positions = new double[LazyLength * contract.JointCount * 3];
                var rotations = new double[LazyLength * contract.JointCount * 4];
                slerpFk = Timing.Measure(() =>
                {
                    slerp.Inbetween(t);
                    ForwardKinematics.Compute(t.Skeleton, LazyLength, t.RootPositions, t.LocalRotations, positions, rotations);
                }, repeats * 4, 1e6);
            }

            double allocated = AllocatedBytesPerTransition(model, contract, 1000);
            return new SpeedResults(transition, network, lazyKeys, lazyFrame, slerpFk, allocated);
        }

        /// <summary>The index of <paramref name="missingFrames"/> in <see cref="Lengths"/>.</summary>
        internal static int IndexOf(int missingFrames)
        {
            int i = Array.IndexOf(LengthList, missingFrames);
            if (i < 0) throw new ArgumentOutOfRangeException(nameof(missingFrames), missingFrames, "not a timed transition length");
            return i;
        }

        /// <summary>The network run alone: a second session, inputs of one request with small random features.</summary>
        private static Timing MeasureNetwork(Func<IInferenceBackend> openNetwork, ModelContract contract, int n, int repeats)
        {
            using IInferenceBackend backend = openNetwork();
            GraphTensors tensors = GraphTensors.Create(contract, ModelGraphKind.Whole, PastFrames, n, n);
            float[] features = tensors.KeyFeatures!.Floats!;
            var random = new Random(1);
            for (int i = 0; i < features.Length; i++) features[i] = (float)(0.2 * (random.NextDouble() - 0.5));
            using IInferenceBinding binding = tensors.Bind(backend);
            return Timing.Measure(binding.Run, repeats, 1e3);
        }

        private static double AllocatedBytesPerTransition(Inbetweener model, ModelContract contract, int calls)
        {
            Transition t = SyntheticTransition.Create(contract, PastFrames, LazyLength);
            var global = new double[LazyLength * contract.JointCount * 3];
            for (int i = 0; i < 10; i++) model.Inbetween(t, global);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < calls; i++) model.Inbetween(t, global);
            return (GC.GetAllocatedBytesForCurrentThread() - before) / (double)calls;
        }
    }
}
