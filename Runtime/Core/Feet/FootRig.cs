using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>One leg's joints: hip (thigh), knee, ankle and toe; −1 for a joint the skeleton lacks (only the toe may be).</summary>
    public readonly struct Leg
    {
        /// <summary>Creates a leg.</summary>
        public Leg(int hip, int knee, int ankle, int toe)
        {
            Hip = hip;
            Knee = knee;
            Ankle = ankle;
            Toe = toe;
        }

        /// <summary>The thigh joint (LaFAN1: LeftUpLeg): its rotation swings the whole leg.</summary>
        public int Hip { get; }

        /// <summary>The knee joint (LaFAN1: LeftLeg).</summary>
        public int Knee { get; }

        /// <summary>The ankle joint (LaFAN1: LeftFoot): the heel's contact point.</summary>
        public int Ankle { get; }

        /// <summary>The toe joint (LaFAN1: LeftToe, at the ball of the foot), or −1 when the skeleton has none.</summary>
        public int Toe { get; }

        /// <summary>True when <see cref="Toe"/> is a joint.</summary>
        public bool HasToe => Toe >= 0;
    }

    /// <summary>
    /// Where a skeleton's legs and feet are and how long its legs are: what contact labelling, foot locking
    /// and the foot-skating measure need. The leg length is <see cref="SkeletonMap"/>'s: the root's height above
    /// its lowest mapped joint in the reference pose, so every threshold "in leg lengths" scales with the
    /// character (and its units) as retargeting does.
    /// </summary>
    public sealed class FootRig
    {
        private readonly int[] _footJoints;

        /// <summary>Creates a rig.</summary>
        /// <param name="skeleton">The skeleton the joint indices refer to.</param>
        /// <param name="left">The left leg.</param>
        /// <param name="right">The right leg.</param>
        /// <param name="legLength">Leg length in the skeleton's units (&gt; 0).</param>
        public FootRig(Skeleton skeleton, Leg left, Leg right, double legLength)
        {
            Skeleton = skeleton ?? throw new ArgumentNullException(nameof(skeleton));
            if (!(legLength > 0) || double.IsInfinity(legLength))
            {
                throw new ArgumentOutOfRangeException(nameof(legLength), $"leg length {legLength}; expected a positive length in the skeleton's units");
            }

            Check(skeleton, left, nameof(left));
            Check(skeleton, right, nameof(right));
            Left = left;
            Right = right;
            LegLength = legLength;
            var feet = new List<int> { left.Ankle };
            if (left.HasToe) feet.Add(left.Toe);
            feet.Add(right.Ankle);
            if (right.HasToe) feet.Add(right.Toe);
            _footJoints = feet.ToArray();
        }

        /// <summary>The skeleton.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>The left leg.</summary>
        public Leg Left { get; }

        /// <summary>The right leg.</summary>
        public Leg Right { get; }

        /// <summary>Leg length in the skeleton's units (the root's height above its lowest mapped joint in the reference pose).</summary>
        public double LegLength { get; }

        /// <summary>The joints that touch the ground: left ankle, left toe (if any), right ankle, right toe (if any).</summary>
        public IReadOnlyList<int> FootJoints => _footJoints;

        internal ReadOnlySpan<int> FootJointSpan => _footJoints;

        /// <summary>Leg 0 (left) or 1 (right).</summary>
        public Leg this[int side] => side == 0 ? Left : side == 1 ? Right : throw new ArgumentOutOfRangeException(nameof(side), "expected 0 (left) or 1 (right)");

        /// <summary>
        /// The rig of the model's skeleton (LaFAN1's joint names: LeftUpLeg, LeftLeg, LeftFoot, LeftToe and the
        /// right ones), its leg length measured on <see cref="ReferencePose.ModelTPose"/> as <see cref="SkeletonMap"/>
        /// measures the target's.
        /// </summary>
        /// <exception cref="ArgumentException">A leg joint is missing; the message names it.</exception>
        public static FootRig ForModel(Skeleton skeleton)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            Leg left = ModelLeg(skeleton, "Left"), right = ModelLeg(skeleton, "Right");
            var all = new int[skeleton.JointCount];
            for (int j = 0; j < all.Length; j++) all[j] = j;
            return new FootRig(skeleton, left, right, LegLengths.Measure(ReferencePose.ModelTPose(skeleton), all, 0));
        }

        /// <summary>True when <paramref name="skeleton"/> has the model's leg joints (LaFAN1 names), so <see cref="ForModel"/> succeeds.</summary>
        public static bool HasModelLegs(Skeleton skeleton)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            foreach (string side in new[] { "Left", "Right" })
            {
                foreach (string joint in new[] { "UpLeg", "Leg", "Foot" })
                {
                    if (skeleton.IndexOf(side + joint) < 0) return false;
                }
            }

            return true;
        }

        /// <summary>
        /// The rig of a map's source skeleton (the user's rig): the source joints the model's leg joints follow,
        /// no toe where the map made the model's toe up, and the map's <see cref="SkeletonMap.SourceLegLength"/>.
        /// </summary>
        /// <param name="map">A map whose target is the model's skeleton (LaFAN1 joint names).</param>
        public static FootRig ForSource(SkeletonMap map)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            Leg Source(Leg m) => new Leg(map.SourceJointOf(m.Hip), map.SourceJointOf(m.Knee), map.SourceJointOf(m.Ankle),
                m.HasToe && !map.IsSynthesized(m.Toe) ? map.SourceJointOf(m.Toe) : -1);
            Skeleton target = map.Target;
            return new FootRig(map.Source, Source(ModelLeg(target, "Left")), Source(ModelLeg(target, "Right")), map.SourceLegLength);
        }

        /// <summary>
        /// The rig of <paramref name="map"/>'s source (<see cref="ForSource"/>) when foot locking can hold its feet:
        /// each leg's thigh, knee and ankle are source joints (not synthesized by the map) and each lies below the
        /// one before (joints between them, such as a twist joint in the thigh, are carried along). Otherwise null,
        /// with <paramref name="problem"/> saying which leg and why, for one warning instead of an exception.
        /// </summary>
        public static FootRig? TryForSource(SkeletonMap map, out string? problem)
        {
            if (map == null) throw new ArgumentNullException(nameof(map));
            Skeleton target = map.Target;
            for (int side = 0; side < 2; side++)
            {
                string name = side == 0 ? "Left" : "Right";
                foreach (string joint in new[] { "UpLeg", "Leg", "Foot" })
                {
                    int t = target.IndexOf(name + joint);
                    if (t < 0 || map.IsSynthesized(t) || map.SourceJointOf(t) < 0)
                    {
                        problem = $"the rig has no joint for the model's {name + joint} (the joint map synthesizes it), so its {name.ToLowerInvariant()} leg has no knee or ankle to bend";
                        return null;
                    }
                }
            }

            FootRig rig = ForSource(map);
            problem = ChainProblem(rig.Skeleton, rig.Left, 0) ?? ChainProblem(rig.Skeleton, rig.Right, 1);
            return problem == null ? rig : null;
        }

        /// <summary>
        /// Null when <paramref name="leg"/> can be bent by two-bone IK: the knee below the thigh, the ankle below the
        /// knee and the toe (if any) below the ankle, directly or through other joints; otherwise what is wrong.
        /// </summary>
        internal static string? ChainProblem(Skeleton skeleton, Leg leg, int side)
        {
            string Name(int j) => skeleton.Names[j];
            string which = side == 0 ? "left" : "right";
            if (!IsBelow(skeleton, leg.Knee, leg.Hip)) return $"the {which} leg's knee {Name(leg.Knee)} is not below its thigh {Name(leg.Hip)}";
            if (!IsBelow(skeleton, leg.Ankle, leg.Knee)) return $"the {which} leg's ankle {Name(leg.Ankle)} is not below its knee {Name(leg.Knee)}";
            if (leg.HasToe && !IsBelow(skeleton, leg.Toe, leg.Ankle)) return $"the {which} leg's toe {Name(leg.Toe)} is not below its ankle {Name(leg.Ankle)}";
            return null;
        }

        /// <summary>
        /// The rest-pose length from <paramref name="ancestor"/> to <paramref name="joint"/> below it: the length of the
        /// summed offsets along the path (every rotation is identity at rest), so a joint between them (a twist joint in
        /// the thigh) does not shorten the bone; for a direct child, its offset's length.
        /// </summary>
        internal double RestLength(int ancestor, int joint)
        {
            Vector3D sum = Vector3D.Zero;
            for (int j = joint; j >= 0 && j != ancestor; j = Skeleton.Parents[j]) sum = sum + Vector3D.Read(Skeleton.OffsetSpan, 3 * j);
            return sum.Length;
        }

        private static bool IsBelow(Skeleton skeleton, int joint, int ancestor)
        {
            for (int j = skeleton.Parents[joint]; j >= 0; j = skeleton.Parents[j])
            {
                if (j == ancestor) return true;
            }

            return false;
        }

        private static Leg ModelLeg(Skeleton skeleton, string side)
        {
            int Find(string name, bool required)
            {
                int j = skeleton.IndexOf(side + name);
                if (j < 0 && required)
                {
                    throw new ArgumentException($"the skeleton has no joint '{side + name}'; expected the model's leg joints (LaFAN1 names: {side}UpLeg, {side}Leg, {side}Foot, optionally {side}Toe)", nameof(skeleton));
                }

                return j;
            }

            return new Leg(Find("UpLeg", true), Find("Leg", true), Find("Foot", true), Find("Toe", false));
        }

        private static void Check(Skeleton skeleton, Leg leg, string name)
        {
            int n = skeleton.JointCount;
            if (leg.Hip <= 0 || leg.Hip >= n || leg.Knee <= 0 || leg.Knee >= n || leg.Ankle <= 0 || leg.Ankle >= n || leg.Toe >= n || leg.Toe == 0 || leg.Toe < -1)
            {
                throw new ArgumentException($"leg joints {leg.Hip}, {leg.Knee}, {leg.Ankle}, {leg.Toe} are not all joints of the {n}-joint skeleton below its root; expected joint indices (toe −1 when absent)", name);
            }
        }
    }
}
