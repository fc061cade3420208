using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inbetweening
{
    /// <summary>
    /// The official interpolation baseline (and the Δ-Interpolator's output baseline): between the last
    /// past key r = P − 1 and the target P + n, missing frame k (1..n) uses a = k / (n + 1); the root
    /// position is LERPed and every joint's local rotation is
    /// normalise(slerp(normalise(q_r), normalise(q_target), a)) with <see cref="Quaternions.Slerp"/>.
    /// </summary>
    /// <remarks>
    /// The official code computes the weights with <c>np.linspace(..., dtype=float32)</c>; we use the
    /// exact k / (n + 1) in double, a difference of ~1e-8 relative, far below the reported digits.
    /// </remarks>
    public sealed class SlerpBaseline : IInbetweener
    {
        /// <inheritdoc />
        public string Id => "slerp";

        /// <inheritdoc />
        public string DisplayName => "Interp.";

        /// <summary>The interpolation weight of missing frame <paramref name="k"/> (0-based) of <paramref name="n"/>.</summary>
        public static double Weight(int k, int n) => (k + 1) / (double)(n + 1);

        /// <inheritdoc />
        public void Inbetween(Transition transition)
        {
            int j = transition.Skeleton.JointCount;
            int n = transition.MissingFrames;
            int last = transition.PastFrames - 1;
            int target = transition.TargetKey;
            double[] keyRoot = transition.KeyRootPositions;
            double[] keyRot = transition.KeyLocalRotations;
            Vector3D p0 = Vector3D.Read(keyRoot, last * 3);
            Vector3D p1 = Vector3D.Read(keyRoot, target * 3);
            Vector3D delta = p1 - p0;
            for (int k = 0; k < n; k++)
            {
                double a = Weight(k, n);
                (p0 + a * delta).Write(transition.RootPositions, k * 3);
            }

            for (int joint = 0; joint < j; joint++)
            {
                var pair = new SlerpPair(
                    Quaternions.Normalize(QuaternionD.Read(keyRot, (last * j + joint) * 4)),
                    Quaternions.Normalize(QuaternionD.Read(keyRot, (target * j + joint) * 4)));
                for (int k = 0; k < n; k++)
                {
                    QuaternionD q = pair.At(Weight(k, n));
                    Quaternions.Normalize(q).Write(transition.LocalRotations, (k * j + joint) * 4);
                }
            }
        }
    }
}
