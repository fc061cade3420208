using System;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The rigid change of frame that puts a request in the network's canonical frame: the yaw that turns
    /// the last past key to face the model's forward axis, and the ground point under its root.
    /// </summary>
    public readonly struct Localization
    {
        /// <summary>Creates a localization.</summary>
        public Localization(QuaternionD yaw, Vector3D origin, double unitScale)
        {
            Yaw = yaw;
            Origin = origin;
            UnitScale = unitScale;
        }

        /// <summary>Rotation about +Y applied to the request (world → model frame).</summary>
        public QuaternionD Yaw { get; }

        /// <summary>Root position at the reference frame with Y = 0, data units.</summary>
        public Vector3D Origin { get; }

        /// <summary>Model units per data unit.</summary>
        public double UnitScale { get; }

        /// <summary>World root position (data units) → localized (model units): yaw · (p − origin) · scale.</summary>
        public Vector3D LocalizePosition(Vector3D p) => UnitScale * Quaternions.Apply(Yaw, p - Origin);

        /// <summary>Localized root position (model units) → world (data units): yaw⁻¹ · (p / scale) + origin.</summary>
        public Vector3D UnlocalizePosition(Vector3D p) => Quaternions.Apply(Quaternions.Conjugate(Yaw), (1.0 / UnitScale) * p) + Origin;

        /// <summary>World root rotation → localized: yaw ⊗ q.</summary>
        public QuaternionD LocalizeRootRotation(QuaternionD q) => Quaternions.Multiply(Yaw, q);

        /// <summary>Localized root rotation → world: yaw⁻¹ ⊗ q.</summary>
        public QuaternionD UnlocalizeRootRotation(QuaternionD q) => Quaternions.Multiply(Quaternions.Conjugate(Yaw), q);
    }

    /// <summary>
    /// Localization of a transition request (Documentation~/model-contract.md, "Localization"; Python
    /// mirror <c>localize.py</c>). The yaw is <see cref="Facing.YawToward"/>. Only the root changes: other joints' rotations are relative to their
    /// parents. Allocation-free.
    /// </summary>
    internal static class Localizer
    {
        /// <summary>
        /// Localizes <paramref name="frameCount"/> frames about <paramref name="referenceFrame"/>.
        /// </summary>
        /// <param name="contract">Supplies the facing axes and unit scale.</param>
        /// <param name="rootPositions">frames × 3 world root positions, data units.</param>
        /// <param name="localRotations">frames × J × 4 local rotations (root's = global).</param>
        /// <param name="frameCount">Number of frames.</param>
        /// <param name="referenceFrame">The last past key r = P − 1.</param>
        /// <param name="localizedRootPositions">Output, frames × 3, model units.</param>
        /// <param name="localizedRotations">Output, frames × J × 4 (non-root joints copied).</param>
        /// <returns>The localization, for <see cref="Localization.UnlocalizePosition"/> and friends.</returns>
        public static Localization Localize(
            ModelContract contract,
            ReadOnlySpan<double> rootPositions,
            ReadOnlySpan<double> localRotations,
            int frameCount,
            int referenceFrame,
            Span<double> localizedRootPositions,
            Span<double> localizedRotations)
        {
            int stride = contract.JointCount * 4;
            QuaternionD yaw = Facing.YawToward(QuaternionD.Read(localRotations, referenceFrame * stride), contract.FacingLocalAxis, contract.FacingTargetAxis);
            Vector3D reference = Vector3D.Read(rootPositions, 3 * referenceFrame);
            var localization = new Localization(yaw, new Vector3D(reference.X, 0.0, reference.Z), contract.UnitScale);
            localRotations.Slice(0, frameCount * stride).CopyTo(localizedRotations);
            for (int f = 0; f < frameCount; f++)
            {
                localization.LocalizePosition(Vector3D.Read(rootPositions, 3 * f)).Write(localizedRootPositions, 3 * f);
                localization.LocalizeRootRotation(QuaternionD.Read(localRotations, f * stride)).Write(localizedRotations, f * stride);
            }

            return localization;
        }
    }
}
