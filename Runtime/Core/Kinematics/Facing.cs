using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Kinematics
{
    /// <summary>
    /// A character's facing: the horizontal direction its root points to. The one definition behind both
    /// the request localization (<c>Inference.Localizer</c>) and the benchmark's window normalisation
    /// (<see cref="WindowNormalization"/>); Python mirror <c>facing.py</c>.
    /// </summary>
    internal static class Facing
    {
        /// <summary>
        /// The rotation about +Y that turns the root's facing onto <paramref name="targetAxis"/>. Facing =
        /// <paramref name="rootRotation"/> applied to <paramref name="localFacingAxis"/>, Y zeroed,
        /// normalised. Apply the result (yaw ⊗ q, yaw · p) to make the root face the target axis.
        /// </summary>
        /// <remarks>
        /// When the horizontal facing is shorter than 1e-6 (the axis points (nearly) straight up or down)
        /// no yaw is defined and the identity is returned. When the facing is exactly opposite to the
        /// target the result is a half turn about +Y (the official LaFAN1 code returns a zero quaternion
        /// there, which would collapse a whole window).
        /// </remarks>
        /// <param name="rootRotation">The root's global rotation (its local rotation).</param>
        /// <param name="localFacingAxis">The root's local facing axis (LaFAN1 hips: +Y).</param>
        /// <param name="targetAxis">The horizontal unit axis to face (the benchmark and the model: +X).</param>
        public static QuaternionD YawToward(QuaternionD rootRotation, Vector3D localFacingAxis, Vector3D targetAxis)
        {
            Vector3D forward = Quaternions.Apply(rootRotation, localFacingAxis);
            forward = new Vector3D(forward.X, 0.0, forward.Z);
            double length = forward.Length;
            if (length < 1e-6)
            {
                return QuaternionD.Identity;
            }

            return Quaternions.Between((1.0 / length) * forward, targetAxis, Vector3D.UnitY);
        }
    }
}
