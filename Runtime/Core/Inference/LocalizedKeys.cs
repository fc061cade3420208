using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The keys of one request in the model's local frame (<see cref="Localizer"/>): what every missing frame of
    /// the request is decoded against — the localized root positions and rotations of its K = P + 1 keys, each
    /// joint's slerp between the last past key and the target (the Δ baseline), and the localization itself
    /// (to put a decoded frame back into the world). Written once per request by <see cref="RowDecoder.Localize"/>.
    /// </summary>
    public sealed class LocalizedKeys
    {
        /// <summary>Buffers for requests of <paramref name="pastFrames"/> past keys (K = P + 1) on <paramref name="contract"/>'s skeleton.</summary>
        public LocalizedKeys(ModelContract contract, int pastFrames)
        {
            int keys = pastFrames + 1;
            int joints = contract.JointCount;
            PastFrames = pastFrames;
            RootPositions = new double[keys * 3];
            LocalRotations = new double[keys * joints * 4];
            Pairs = new SlerpPair[joints];
        }

        /// <summary>P, the past keys.</summary>
        public int PastFrames { get; }

        /// <summary>The keys' root positions, localized (K × 3, model units).</summary>
        public double[] RootPositions { get; }

        /// <summary>The keys' local rotations, localized (K × J × 4, w x y z).</summary>
        public double[] LocalRotations { get; }

        /// <summary>Each joint's slerp between the last past key and the target (localized).</summary>
        internal SlerpPair[] Pairs { get; }

        /// <summary>The request's localization (yaw and origin).</summary>
        public Localization Localization { get; internal set; }
    }
}
