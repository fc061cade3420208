using System;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>
    /// Moves the legs of one pose so that its held foot joints reach their targets: the solve that both the
    /// clip locker (<see cref="FootLocker"/>, bakes) and the run-time locker (<see cref="LiveFootLocker"/>, the
    /// component) apply, given each foot joint's weight (0 free … 1 held) and target.
    /// </summary>
    /// <remarks>
    /// Heel (ankle) held: the ankle goes to its target, the foot keeps its global orientation. Toe held, heel
    /// free (a rolling foot): the foot keeps its orientation and is carried so that the toe lands on its target.
    /// Both held: the foot lies on the line from the heel's to the toe's target, the more held of the two exact
    /// (the toe on a tie). Then analytic two-bone IK (<see cref="TwoBoneIk"/>) with the knee in the leg's plane;
    /// only the thigh, knee and foot rotations change, so a rig whose toe was synthesized (rigid to the foot) is
    /// handled the same way. Allocation-free; not thread-safe.
    /// </remarks>
    internal sealed class LegPinning
    {
        private readonly FootRig _rig;
        private readonly double[] _globalPositions;
        private readonly double[] _globalRotations;

        /// <exception cref="ArgumentException">A leg is not a chain thigh → knee → ankle (→ toe), each joint below the one before (<see cref="FootRig.ChainProblem"/>).</exception>
        public LegPinning(FootRig rig)
        {
            Skeleton s = rig.Skeleton;
            for (int side = 0; side < 2; side++)
            {
                // Joints between them (a twist joint in the thigh) are allowed: they keep their local rotations and
                // ride along, and SolveLeg writes the knee and ankle relative to their own parents.
                string? problem = FootRig.ChainProblem(s, rig[side], side);
                if (problem != null)
                {
                    throw new ArgumentException(problem + "; expected thigh → knee → ankle (→ toe), each below the one before, as on the model's skeleton", nameof(rig));
                }
            }

            _rig = rig;
            _globalPositions = new double[3 * rig.Skeleton.JointCount];
            _globalRotations = new double[4 * rig.Skeleton.JointCount];
        }

        /// <summary>Global joint positions of the pose given to <see cref="ComputeGlobals"/> (joints × 3).</summary>
        public double[] GlobalPositions => _globalPositions;

        /// <summary>Forward kinematics of one pose (local translations with the root's position first, local rotations).</summary>
        public void ComputeGlobals(ReadOnlySpan<double> localPositions, ReadOnlySpan<double> localRotations)
        {
            ForwardKinematics.ComputeFrame(_rig.Skeleton.ParentSpan, localPositions, Vector3D.Read(localPositions, 0), localRotations, _globalPositions, _globalRotations);
        }

        /// <summary>
        /// After <see cref="ComputeGlobals"/> of the same pose: pins its foot joints. <paramref name="weights"/> holds
        /// one weight per channel (left ankle, left toe, right ankle, right toe), <paramref name="targets"/> their
        /// targets (channels × 3); a leg whose two weights are 0 is left alone.
        /// </summary>
        public void Pin(ReadOnlySpan<double> weights, ReadOnlySpan<double> targets, Span<double> localRotations) => Pin(weights, targets, default, localRotations);

        /// <summary>
        /// <see cref="Pin(ReadOnlySpan{double}, ReadOnlySpan{double}, Span{double})"/>, and where a held heel's free toe would end
        /// below <paramref name="toeFloors"/> (per side, a height; empty for none), the foot is pitched up about the heel until
        /// the toe is on it: keeping the motion's foot orientation while the heel is held lower than the motion had it
        /// would push the toe into the floor.
        /// </summary>
        public void Pin(ReadOnlySpan<double> weights, ReadOnlySpan<double> targets, ReadOnlySpan<double> toeFloors, Span<double> localRotations)
        {
            for (int side = 0; side < 2; side++)
            {
                double wa = weights[2 * side];
                double wt = weights[2 * side + 1];
                if (wa <= 0 && wt <= 0) continue;
                Leg leg = _rig[side];
                Vector3D ankle = Vector3D.Read(_globalPositions, 3 * leg.Ankle);
                QuaternionD foot = QuaternionD.Read(_globalRotations, 4 * leg.Ankle);
                Vector3D toeVector = leg.HasToe ? Vector3D.Read(_globalPositions, 3 * leg.Toe) - ankle : Vector3D.Zero;
                // Heel: the ankle towards its target, the foot's orientation kept (the toe carried along).
                Vector3D heel = wa > 0 ? Lerp(ankle, Vector3D.Read(targets, 3 * (2 * side)), wa) : ankle;
                Vector3D target = heel;
                QuaternionD footWanted = foot;
                if (wt > 0)
                {
                    // Toe: a rolling foot (heel free) keeps its orientation and is carried so that the toe lands on its
                    // target; with the heel planted too the foot lies along the line from heel to toe target, the ankle
                    // on it at the foot's length from the toe (the more held of the two joints is the one that is exact).
                    double length = toeVector.Length;
                    Vector3D toeGoal = Lerp(heel + toeVector, Vector3D.Read(targets, 3 * (2 * side + 1)), wt);
                    Vector3D carried = toeGoal - toeVector;
                    Vector3D along = toeGoal - heel;
                    double span = along.Length;
                    if (wa > 0 && span > 1e-9 * length)
                    {
                        Vector3D unit = (1.0 / span) * along;
                        Vector3D heelExact = heel, toeExact = toeGoal - length * unit;
                        // The more held joint is exact (the toe on a tie): the other lies on the line, a foot's length away.
                        Vector3D flat = wt >= wa ? toeExact : heelExact;
                        target = Lerp(carried, flat, wa);
                        if (wt >= wa)
                        {
                            // Back onto the sphere about the toe's target: the toe stays exact however the heel eases.
                            Vector3D arm = target - toeGoal;
                            double armLength = arm.Length;
                            if (armLength > 1e-9 * length) target = toeGoal + (length / armLength) * arm;
                        }
                    }
                    else
                    {
                        target = carried;
                    }

                    footWanted = Quaternions.Normalize(Quaternions.Multiply(Quaternions.Between(toeVector, toeGoal - target, Vector3D.UnitY), foot));
                }

                if (leg.HasToe && toeFloors.Length == 2)
                {
                    // Wherever the blend of held and free joints put the foot, its toe does not go below the floor: same
                    // length and heading, pitched up about the ankle until the toe stands on it.
                    Vector3D toeNow = Quaternions.Apply(Quaternions.Multiply(footWanted, Quaternions.Conjugate(foot)), toeVector);
                    double length = toeNow.Length, flat = Math.Sqrt(toeNow.X * toeNow.X + toeNow.Z * toeNow.Z);
                    if (target.Y + toeNow.Y < toeFloors[side] && flat > 1e-9 * length)
                    {
                        double y = Math.Max(-length, Math.Min(length, toeFloors[side] - target.Y));
                        double h = Math.Sqrt(length * length - y * y) / flat;
                        var lifted = new Vector3D(h * toeNow.X, y, h * toeNow.Z);
                        footWanted = Quaternions.Normalize(Quaternions.Multiply(Quaternions.Between(toeNow, lifted, Vector3D.UnitY), footWanted));
                    }
                }

                SolveLeg(leg, target, footWanted, toeVector, localRotations);
            }
        }

        private void SolveLeg(Leg leg, Vector3D target, QuaternionD footWanted, Vector3D toeVector, Span<double> localRotations)
        {
            Skeleton s = _rig.Skeleton;
            int parent = s.Parents[leg.Hip];
            Vector3D hip = Vector3D.Read(_globalPositions, 3 * leg.Hip);
            Vector3D knee = Vector3D.Read(_globalPositions, 3 * leg.Knee);
            Vector3D ankle = Vector3D.Read(_globalPositions, 3 * leg.Ankle);
            QuaternionD hipGlobal = QuaternionD.Read(_globalRotations, 4 * leg.Hip);
            QuaternionD kneeGlobal = QuaternionD.Read(_globalRotations, 4 * leg.Knee);
            // A straight knee bends towards where the foot points (or, without a toe, the root's forward +Z).
            Vector3D hint = leg.HasToe ? toeVector : Quaternions.Apply(QuaternionD.Read(_globalRotations, 0), Vector3D.UnitZ);
            TwoBoneIk.Solve(hip, knee, ankle, hipGlobal, kneeGlobal, target, hint, out QuaternionD newHip, out QuaternionD newKnee);
            QuaternionD parentGlobal = QuaternionD.Read(_globalRotations, 4 * parent);
            Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(parentGlobal), newHip)).Write(localRotations, 4 * leg.Hip);
            QuaternionD kneeParent = NewParentGlobal(leg.Knee, leg.Hip, hipGlobal, newHip);
            Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(kneeParent), newKnee)).Write(localRotations, 4 * leg.Knee);
            QuaternionD ankleParent = NewParentGlobal(leg.Ankle, leg.Knee, kneeGlobal, newKnee);
            Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(ankleParent), footWanted)).Write(localRotations, 4 * leg.Ankle);
        }

        /// <summary>
        /// The global rotation of <paramref name="joint"/>'s parent once <paramref name="solved"/> turned from
        /// <paramref name="oldGlobal"/> to <paramref name="newGlobal"/>: the solved joint itself when it is the parent,
        /// otherwise the parent turned with it (the joints between keep their local rotations).
        /// </summary>
        private QuaternionD NewParentGlobal(int joint, int solved, QuaternionD oldGlobal, QuaternionD newGlobal)
        {
            int parent = _rig.Skeleton.Parents[joint];
            if (parent == solved) return newGlobal;
            QuaternionD turn = Quaternions.Multiply(newGlobal, Quaternions.Conjugate(oldGlobal));
            return Quaternions.Normalize(Quaternions.Multiply(turn, QuaternionD.Read(_globalRotations, 4 * parent)));
        }

        internal static Vector3D Lerp(Vector3D a, Vector3D b, double t) => a + t * (b - a);
    }
}
