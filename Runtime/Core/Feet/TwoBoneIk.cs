using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>
    /// Analytic two-bone IK (hip → knee → ankle): bends the knee so that the hip–ankle distance matches the
    /// target's, keeping the knee in the leg's current plane, then swings the whole leg about the hip onto
    /// the target. Lengths are never changed: a target out of reach leaves the leg as straight as it may be,
    /// pointing at it.
    /// </summary>
    /// <remarks>
    /// The plane is the one through hip, knee and ankle (its normal n = (ankle − hip) × (knee − hip)). A leg
    /// nearly straight has no plane of its own: <c>bendHint</c> (the direction the knee should bend towards,
    /// e.g. the foot's forward direction) then supplies it, blended in smoothly so that the knee never flips.
    /// Written in world space: rotating a joint's global rotation by R turns everything below it by R.
    /// </remarks>
    public static class TwoBoneIk
    {
        /// <summary>How straight the leg may get: the hip–ankle distance is at most this fraction of thigh + shin.</summary>
        public const double MaxExtension = 0.99999;

        /// <summary>
        /// Solves for new global rotations of the hip and the knee that put the ankle at <paramref name="target"/>
        /// (or as close as the bone lengths allow).
        /// </summary>
        /// <param name="hip">Hip position (does not move).</param>
        /// <param name="knee">Knee position.</param>
        /// <param name="ankle">Ankle position.</param>
        /// <param name="hipGlobal">Hip's global rotation.</param>
        /// <param name="kneeGlobal">Knee's global rotation.</param>
        /// <param name="target">Where the ankle should go.</param>
        /// <param name="bendHint">A direction the knee bends towards when the leg is straight (need not be unit).</param>
        /// <param name="newHipGlobal">The hip's new global rotation.</param>
        /// <param name="newKneeGlobal">The knee's new global rotation.</param>
        /// <returns>The ankle's position after the solve.</returns>
        public static Vector3D Solve(
            Vector3D hip, Vector3D knee, Vector3D ankle, QuaternionD hipGlobal, QuaternionD kneeGlobal, Vector3D target, Vector3D bendHint,
            out QuaternionD newHipGlobal, out QuaternionD newKneeGlobal)
        {
            Vector3D ab = knee - hip, bc = ankle - knee, ac = ankle - hip, at = target - hip;
            double lab = ab.Length, lcb = bc.Length, lac = ac.Length;
            double lat = Clamp(at.Length, Math.Abs(lab - lcb) * (1 + 1e-9) + 1e-12, (lab + lcb) * MaxExtension);
            if (lab < 1e-12 || lcb < 1e-12 || lac < 1e-12)
            {
                newHipGlobal = hipGlobal;
                newKneeGlobal = kneeGlobal;
                return ankle;
            }

            // The leg's plane; a nearly straight leg takes it from the hint, blended in as the bend vanishes.
            Vector3D n = Vector3D.Cross(ac, ab);
            Vector3D hintNormal = Vector3D.Cross(ac, bendHint);
            double hl = hintNormal.Length;
            if (hl > 1e-12) n = n + (1e-3 * lac * lab / hl) * hintNormal;
            double nl = n.Length;
            if (nl < 1e-12 * lac * lab)
            {
                // Straight leg and a hint along it: any normal perpendicular to the leg.
                n = Vector3D.Cross(ac, Math.Abs(ac.X) < 0.9 * lac ? Vector3D.UnitX : Vector3D.UnitZ);
                nl = n.Length;
            }

            Vector3D axis = (1.0 / nl) * n;

            // Interior angles now and wanted (law of cosines).
            double hipAngle0 = Angle(ac, ab), hipAngle1 = Math.Acos(Clamp((lab * lab + lat * lat - lcb * lcb) / (2 * lab * lat), -1, 1));
            double kneeAngle0 = Angle(hip - knee, ankle - knee), kneeAngle1 = Math.Acos(Clamp((lab * lab + lcb * lcb - lat * lat) / (2 * lab * lcb), -1, 1));
            QuaternionD hipBend = Quaternions.FromAxisAngle(axis, hipAngle1 - hipAngle0);
            QuaternionD kneeBend = Quaternions.FromAxisAngle(axis, kneeAngle1 - kneeAngle0);

            // Bend within the plane: the hip turns by hipBend, the shin by hipBend and kneeBend.
            QuaternionD shinTurn = Quaternions.Multiply(hipBend, kneeBend);
            Vector3D bentKnee = hip + Quaternions.Apply(hipBend, ab);
            Vector3D bentAnkle = bentKnee + Quaternions.Apply(shinTurn, bc);

            // Swing the bent leg about the hip onto the target.
            QuaternionD swing = Quaternions.Between(bentAnkle - hip, at, axis);
            newHipGlobal = Quaternions.Normalize(Quaternions.Multiply(swing, Quaternions.Multiply(hipBend, hipGlobal)));
            newKneeGlobal = Quaternions.Normalize(Quaternions.Multiply(swing, Quaternions.Multiply(shinTurn, kneeGlobal)));
            return hip + Quaternions.Apply(swing, bentAnkle - hip);
        }

        private static double Angle(Vector3D a, Vector3D b)
        {
            // atan2 of |a × b| and a · b: accurate near 0 and π, where acos is not.
            return Math.Atan2(Vector3D.Cross(a, b).Length, Vector3D.Dot(a, b));
        }

        private static double Clamp(double v, double lo, double hi) => v < lo ? lo : v > hi ? hi : v;
    }
}
