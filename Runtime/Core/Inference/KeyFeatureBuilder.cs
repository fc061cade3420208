using System;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Fills the <c>key_features</c> input [1, K, 9·J] (input Δ-mode <c>last_pose</c>; Python mirror
    /// <c>features.key_features</c>): for key frame t and joint j, the local 6D rotation minus the root's
    /// 6D at the reference key, then the global position (FK of the localized frame, model units) minus
    /// the root position at the reference key. One instance per model; allocation-free after construction.
    /// </summary>
    public sealed class KeyFeatureBuilder
    {
        private readonly int[] _parents;
        private readonly double[] _scaledOffsets;
        private readonly double[] _globalPositions;
        private readonly double[] _globalRotations;

        /// <summary>Creates a builder for the model's skeleton (offsets scaled to model units once).</summary>
        public KeyFeatureBuilder(ModelContract contract)
        {
            int j = contract.JointCount;
            _parents = new int[j];
            _scaledOffsets = new double[3 * j];
            for (int k = 0; k < j; k++) _parents[k] = contract.Skeleton.Parents[k];
            for (int i = 0; i < 3 * j; i++) _scaledOffsets[i] = contract.Skeleton.Offsets[i] * contract.UnitScale;
            _globalPositions = new double[3 * j];
            _globalRotations = new double[4 * j];
        }

        /// <summary>Tensor name this builder fills.</summary>
        public static string TensorName => TensorNames.KeyFeatures;

        /// <summary>Number of joints J.</summary>
        public int JointCount => _parents.Length;

        /// <summary>Writes K × 9J features.</summary>
        /// <param name="localizedRootPositions">K × 3 localized root positions, model units.</param>
        /// <param name="localizedRotations">K × J × 4 localized local rotations.</param>
        /// <param name="keyCount">K = P + 1.</param>
        /// <param name="referenceKey">Index of the reference key r = P − 1 among the keys.</param>
        /// <param name="features">Output, K × 9J floats.</param>
        public void Build(ReadOnlySpan<double> localizedRootPositions, ReadOnlySpan<double> localizedRotations, int keyCount, int referenceKey, Span<float> features)
        {
            int jc = JointCount;
            int width = ModelContract.FeaturesPerJoint * jc;
            if (features.Length < keyCount * width) throw new ArgumentException($"features must hold {keyCount} × {width} values", nameof(features));

            // Reference: the root's 6D and position at key r (its global position is the root position).
            Matrix3x3D refMatrix = Quaternions.ToMatrix(Quaternions.Normalize(QuaternionD.Read(localizedRotations, referenceKey * jc * 4)));
            double r0 = refMatrix.M00, r1 = refMatrix.M01, r2 = refMatrix.M02, r3 = refMatrix.M10, r4 = refMatrix.M11, r5 = refMatrix.M12;
            Vector3D refPosition = Vector3D.Read(localizedRootPositions, 3 * referenceKey);

            for (int t = 0; t < keyCount; t++)
            {
                ReadOnlySpan<double> rotations = localizedRotations.Slice(t * jc * 4, jc * 4);
                ForwardKinematics.ComputeFrame(_parents, _scaledOffsets, Vector3D.Read(localizedRootPositions, 3 * t), rotations, _globalPositions, _globalRotations);
                Span<float> row = features.Slice(t * width, width);
                for (int j = 0; j < jc; j++)
                {
                    Matrix3x3D m = Quaternions.ToMatrix(Quaternions.Normalize(QuaternionD.Read(rotations, 4 * j)));
                    int o = 9 * j;
                    row[o] = (float)(m.M00 - r0);
                    row[o + 1] = (float)(m.M01 - r1);
                    row[o + 2] = (float)(m.M02 - r2);
                    row[o + 3] = (float)(m.M10 - r3);
                    row[o + 4] = (float)(m.M11 - r4);
                    row[o + 5] = (float)(m.M12 - r5);
                    row[o + 6] = (float)(_globalPositions[3 * j] - refPosition.X);
                    row[o + 7] = (float)(_globalPositions[3 * j + 1] - refPosition.Y);
                    row[o + 8] = (float)(_globalPositions[3 * j + 2] - refPosition.Z);
                }
            }
        }
    }
}
