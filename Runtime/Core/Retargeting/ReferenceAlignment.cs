using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Turns a target's declared reference pose so that it matches a source's (see <see cref="SkeletonMap"/>'s
    /// remarks): the root by the yaw that best matches the horizontal directions to its children, then,
    /// parents first, every joint with one child by the shortest arc that makes its bone point like the
    /// source's. The result is one global rotation per target joint to put in front of the declared one.
    /// </summary>
    internal static class ReferenceAlignment
    {
        /// <summary>
        /// Per target joint, the rotation that aligns its declared global rotation to the source;
        /// <paramref name="aligned"/> says which bones were compared (the rest turn with their parent).
        /// </summary>
        public static QuaternionD[] Align(ReferencePose source, ReferencePose target, int[] sourceOf, int[] sourceFirst, out bool[] aligned)
        {
            Skeleton ts = target.Skeleton;
            int jt = ts.JointCount;
            var align = new QuaternionD[jt];
            align[0] = RootYaw(source, target, sourceOf, sourceFirst);
            double sourceEps = 1e-6 * LongestBone(source), targetEps = 1e-6 * LongestBone(target);
            var children = new List<int>[jt];
            for (int j = 0; j < jt; j++) children[j] = new List<int>();
            for (int j = 1; j < jt; j++) children[ts.Parents[j]].Add(j);
            aligned = new bool[jt];
            for (int j = 1; j < jt; j++)
            {
                QuaternionD inherited = align[ts.Parents[j]];
                align[j] = inherited;
                if (children[j].Count != 1) continue;
                int c = children[j][0];
                Vector3D a = target.GlobalPosition(c) - target.GlobalPosition(j);
                Vector3D b = source.GlobalPosition(sourceFirst[c]) - source.GlobalPosition(sourceOf[j]);
                if (a.Length <= targetEps || b.Length <= sourceEps) continue;
                Vector3D from = Quaternions.Apply(inherited, a);
                align[j] = Quaternions.Normalize(Quaternions.Multiply(Quaternions.Between(from, b, Vector3D.UnitY), inherited));
                aligned[j] = true;
            }

            return align;
        }

        public static QuaternionD RootYaw(ReferencePose source, ReferencePose target, int[] sourceOf, int[] sourceFirst)
        {
            // Least-squares yaw between the horizontal parts of unit directions from the root to joints of
            // the target and from s(root) to their source counterparts: θ = atan2(Σ (a × b)·Y, Σ a·b).
            // The root's own children come first: they move rigidly with the root, so a reference pose whose
            // limbs differ from the target's (arms lowered, legs spread) does not bias the yaw. Only when
            // they give no horizontal direction (e.g. all of zero length) every joint is used.
            Skeleton ts = target.Skeleton;
            for (int pass = 0; pass < 2; pass++)
            {
                double cross = 0, dot = 0, weight = 0;
                Vector3D t0 = target.GlobalPosition(0), s0 = source.GlobalPosition(sourceOf[0]);
                for (int k = 1; k < ts.JointCount; k++)
                {
                    if (pass == 0 && ts.Parents[k] != 0) continue;
                    Vector3D a = target.GlobalPosition(k) - t0, b = source.GlobalPosition(sourceFirst[k]) - s0;
                    double la = a.Length, lb = b.Length;
                    if (la < 1e-12 || lb < 1e-12) continue;
                    a = (1.0 / la) * a;
                    b = (1.0 / lb) * b;
                    cross += a.Z * b.X - a.X * b.Z;
                    dot += a.X * b.X + a.Z * b.Z;
                    weight += Math.Sqrt((a.X * a.X + a.Z * a.Z) * (b.X * b.X + b.Z * b.Z));
                }

                if (weight < 0.5 && pass == 0) continue;
                double half = 0.5 * Math.Atan2(cross, dot);
                return new QuaternionD(Math.Cos(half), 0.0, Math.Sin(half), 0.0);
            }

            return QuaternionD.Identity;
        }

        public static double LongestBone(ReferencePose pose)
        {
            double longest = 0;
            ReadOnlySpan<double> o = pose.Skeleton.OffsetSpan;
            for (int j = 1; j < pose.Skeleton.JointCount; j++) longest = Math.Max(longest, Vector3D.Read(o, 3 * j).Length);
            return longest;
        }
    }
}
