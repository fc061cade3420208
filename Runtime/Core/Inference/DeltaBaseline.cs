using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// What the network's deltas are added to, per output Δ-mode (Python mirror <c>baseline.py</c>):
    /// for <see cref="OutputDeltaMode.Slerp"/>, query frame f uses a = (f − r) / (n + 1), the root LERPs
    /// between the last past key r and the target, and each joint's rotation is
    /// normalise(slerp(normalise(q_r), normalise(q_target), a)) with the official benchmark's
    /// <see cref="Quaternions.Slerp"/>. Works on localized values.
    /// </summary>
    internal static class DeltaBaseline
    {
        /// <summary>The interpolation weight of missing frame <paramref name="k"/> (0-based) of a gap of <paramref name="n"/>: (k + 1) / (n + 1).</summary>
        public static double Weight(int k, int n) => Inbetweening.SlerpBaseline.Weight(k, n);

        /// <summary>Baseline root position of a missing frame (model units).</summary>
        /// <param name="mode">Output Δ-mode.</param>
        /// <param name="last">Localized root position at the last past key.</param>
        /// <param name="target">Localized root position at the target key.</param>
        /// <param name="weight">a = (f − r) / (n + 1).</param>
        public static Vector3D RootPosition(OutputDeltaMode mode, Vector3D last, Vector3D target, double weight)
        {
            switch (mode)
            {
                case OutputDeltaMode.Slerp: return last + weight * (target - last);
                case OutputDeltaMode.LastPose: return last;
                default: return Vector3D.Zero;
            }
        }

        /// <summary>
        /// Baseline rotation of one joint in a missing frame (unit). For <see cref="OutputDeltaMode.None"/>
        /// this is still the SLERP rotation: it serves as the hemisphere reference, while its 6D baseline
        /// is zero (see <see cref="OutputDecoder"/>).
        /// </summary>
        /// <param name="mode">Output Δ-mode.</param>
        /// <param name="pair">The joint's normalised rotations at the last past key and the target, prepared once per transition.</param>
        /// <param name="weight">a = (f − r) / (n + 1).</param>
        public static QuaternionD Rotation(OutputDeltaMode mode, in SlerpPair pair, double weight)
        {
            if (mode == OutputDeltaMode.LastPose) return pair.From;
            return Quaternions.Normalize(pair.At(weight));
        }
    }
}
