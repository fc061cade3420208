using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The one decode path from a request to its frames, whatever runs the network: <see cref="Localize"/> puts
    /// a request's keys into the model's frame and builds their <c>key_features</c>;
    /// <see cref="Decode(Transition, LocalizedKeys, OutputRow, int, double[], double[])"/> turns one network output
    /// row (<see cref="OutputRow"/>) into one missing frame in the world (the Δ baseline plus the row's deltas through
    /// <see cref="OutputDecoder"/>, un-localized); <see cref="Baseline"/> gives the same frame without the network
    /// (SLERP). The whole-transition run, the lazy runs and the batched schedulers all go through it, so every path
    /// is the same maths.
    /// </summary>
    /// <remarks>Allocation-free. Holds the feature builder's scratch buffers, so use one per thread.</remarks>
    public sealed class RowDecoder
    {
        private readonly KeyFeatureBuilder _features;

        /// <summary>A decoder for requests on <paramref name="contract"/>'s model.</summary>
        public RowDecoder(ModelContract contract)
        {
            Contract = contract ?? throw new ArgumentNullException(nameof(contract));
            _features = new KeyFeatureBuilder(contract);
        }

        /// <summary>The model's contract (skeleton, delta modes).</summary>
        public ModelContract Contract { get; }

        /// <summary>
        /// Localizes the keys of <paramref name="transition"/> into <paramref name="keys"/>, writes their K × 9J
        /// features into <paramref name="keyFeatures"/> (a request's own buffer or a row of a batch), and prepares
        /// each joint's slerp between the last past key and the target once, for every missing frame's baseline.
        /// </summary>
        public void Localize(Transition transition, LocalizedKeys keys, Span<float> keyFeatures)
        {
            Transition t = transition;
            int count = t.KeyFrameCount;
            int reference = t.PastFrames - 1;
            keys.Localization = Localizer.Localize(Contract, t.KeyRootPositions, t.KeyLocalRotations, count, reference, keys.RootPositions, keys.LocalRotations);
            _features.Build(keys.RootPositions, keys.LocalRotations, count, reference, keyFeatures);
            int jc = Contract.JointCount;
            int target = t.PastFrames;
            double[] rotations = keys.LocalRotations;
            for (int j = 0; j < jc; j++)
            {
                keys.Pairs[j] = new SlerpPair(
                    Quaternions.Normalize(QuaternionD.Read(rotations, (reference * jc + j) * 4)),
                    Quaternions.Normalize(QuaternionD.Read(rotations, (target * jc + j) * 4)));
            }
        }

        /// <summary>
        /// Decodes <paramref name="row"/> into missing frame <paramref name="k"/> (0..n−1) of <paramref name="transition"/>,
        /// world space, into <paramref name="roots"/> (n × 3) and <paramref name="rotations"/> (n × J × 4) at k, and its
        /// predicted foot contacts, when the model gives them, into the transition's <see cref="Transition.FootContacts"/> at k.
        /// </summary>
        public void Decode(Transition transition, LocalizedKeys keys, OutputRow row, int k, double[] roots, double[] rotations) =>
            Decode(transition, keys, row, k, roots, rotations, null);

        /// <summary>
        /// <see cref="Decode(Transition, LocalizedKeys, OutputRow, int, double[], double[])"/> with the request's SLERP
        /// frames as <see cref="Baseline"/> wrote them (n × J × 4, <paramref name="slerpRotations"/>; null: computed here):
        /// every joint but the root reads its Δ baseline from there instead of evaluating the slerp again — the same
        /// doubles, since both come from the same <see cref="SlerpPair"/> at the same weight — so a scheduler that
        /// decodes many rows per frame reads 4 values per joint instead of the joint's slerp constants and two sines.
        /// </summary>
        internal void Decode(Transition transition, LocalizedKeys keys, OutputRow row, int k, double[] roots, double[] rotations, double[]? slerpRotations)
        {
            int jc = Contract.JointCount;
            int last = transition.PastFrames - 1;
            int target = transition.PastFrames;
            OutputDeltaMode mode = Contract.OutputDeltaMode;
            double a = DeltaBaseline.Weight(k, transition.MissingFrames);
            Localization loc = keys.Localization;
            double[] localRoot = keys.RootPositions;
            Vector3D baseRoot = DeltaBaseline.RootPosition(mode, Vector3D.Read(localRoot, 3 * last), Vector3D.Read(localRoot, 3 * target), a);
            Vector3D root = OutputDecoder.RootPosition(baseRoot, row.RootPositionDelta);
            loc.UnlocalizePosition(root).Write(roots, 3 * k);
            ReadOnlySpan<float> deltas = row.Rotation6DDelta;
            // Baseline wrote the slerp for output Δ-modes slerp and none alike (mode none uses it as the hemisphere
            // reference only); the root's there is un-localized, so the root's is always evaluated here.
            bool stored = slerpRotations != null && mode != OutputDeltaMode.LastPose;
            for (int j = 0; j < jc; j++)
            {
                QuaternionD baseRotation = stored && j > 0 ? QuaternionD.Read(slerpRotations!, (k * jc + j) * 4) : DeltaBaseline.Rotation(mode, keys.Pairs[j], a);
                QuaternionD q = OutputDecoder.Rotation(mode, baseRotation, deltas.Slice(j * 6, 6));
                if (j == 0) q = loc.UnlocalizeRootRotation(q);
                q.Write(rotations, (k * jc + j) * 4);
            }

            // The row's predicted contacts go to the request (every decode path comes here): lockers plant feet by them.
            transition.HasFootContacts = !row.FootContacts.IsEmpty;
            transition.ContactThreshold = Contract.ContactThreshold;
            if (transition.HasFootContacts) row.FootContacts.CopyTo(new Span<float>(transition.FootContacts, Transition.ContactChannels * k, Transition.ContactChannels));
        }

        /// <summary>
        /// The SLERP pose of missing frame <paramref name="k"/> of the same request, world space: the baseline the
        /// network's Δ is added to (output Δ-mode <c>slerp</c>; other modes get SLERP too), what a frame shows while
        /// its network output has not arrived.
        /// </summary>
        public void Baseline(Transition transition, LocalizedKeys keys, int k, double[] roots, double[] rotations)
        {
            int jc = Contract.JointCount;
            int last = transition.PastFrames - 1;
            int target = transition.PastFrames;
            double a = DeltaBaseline.Weight(k, transition.MissingFrames);
            Localization loc = keys.Localization;
            double[] localRoot = keys.RootPositions;
            Vector3D root = DeltaBaseline.RootPosition(OutputDeltaMode.Slerp, Vector3D.Read(localRoot, 3 * last), Vector3D.Read(localRoot, 3 * target), a);
            loc.UnlocalizePosition(root).Write(roots, 3 * k);
            for (int j = 0; j < jc; j++)
            {
                QuaternionD q = DeltaBaseline.Rotation(OutputDeltaMode.Slerp, keys.Pairs[j], a);
                if (j == 0) q = loc.UnlocalizeRootRotation(q);
                q.Write(rotations, (k * jc + j) * 4);
            }
        }
    }
}
