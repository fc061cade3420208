using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>
    /// Skeletons and motion for the retargeting tests: LaFAN1's 22-joint hierarchy with its file offsets
    /// (the model's skeleton), and a generated source skeleton of the same joints with other rest
    /// orientations, proportions and units.
    /// </summary>
    internal static class RetargetFixtures
    {
        /// <summary>LaFAN1's joints, parents and offsets (cm) as in its BVH headers (dance1_subject1.bvh), root at the origin.</summary>
        public static Skeleton Lafan1()
        {
            string[] names =
            {
                "Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToe", "RightUpLeg", "RightLeg", "RightFoot", "RightToe",
                "Spine", "Spine1", "Spine2", "Neck", "Head", "LeftShoulder", "LeftArm", "LeftForeArm", "LeftHand",
                "RightShoulder", "RightArm", "RightForeArm", "RightHand",
            };
            int[] parents = { -1, 0, 1, 2, 3, 0, 5, 6, 7, 0, 9, 10, 11, 12, 11, 14, 15, 16, 11, 18, 19, 20 };
            double[] offsets =
            {
                0, 0, 0,
                0.103456, 1.857829, 10.548507, 43.5, 0, 0, 42.3722, 0, 0, 17.299992, 0, 0,
                0.10346, 1.857824, -10.548508, 43.500042, 0, 0, 42.372265, 0, 0, 17.299999, 0, 0,
                6.901965, -2.603734, 0, 12.588102, 0, 0, 12.343201, 0, 0, 25.832899, 0, 0, 11.766603, 0, 0,
                19.745899, -1.480371, 6.000098, 11.284129, 0, 0, 33.000046, 0, 0, 25.20001, 0, 0,
                19.746092, -1.480375, -6.000075, 11.284135, 0, 0, 33.000092, 0, 0, 25.19978, 0, 0,
            };
            return new Skeleton(names, parents, offsets);
        }

        /// <summary>
        /// A source skeleton with the target's joints renamed "src_NAME", every joint's rest frame turned
        /// at random (so its zero pose is unlike the target's), every bone scaled by its own factor in
        /// [0.7, 1.4], units × <paramref name="unit"/>, plus two joints the target lacks: a zero-offset
        /// "src_LeftHipJoint" between the hips and the left thigh and a finger "src_LeftFinger" below the left
        /// hand. Its reference pose has the target's T-pose bone directions, turned by <paramref name="yawDegrees"/>
        /// about Y, except for the single-child limb joints listed in <paramref name="perturbed"/>, which are
        /// turned by random rotations of up to 25°.
        /// </summary>
        public static (Skeleton Skeleton, ReferencePose Reference) Source(Skeleton target, int seed, double unit, double yawDegrees, params string[] perturbed)
        {
            var rng = new TestRandom(seed);
            ReferencePose tpose = ReferencePose.ModelTPose(target);
            int jt = target.JointCount;
            QuaternionD yaw = Quaternions.FromAxisAngle(Vector3D.UnitY, yawDegrees * Math.PI / 180.0);

            // Source joint order: the target's, with the two extra joints inserted.
            var names = new List<string>();
            var parents = new List<int>();
            var targetOf = new List<int>();   // source joint → target joint (−1 for the extras)
            var sourceIndex = new int[jt];
            for (int j = 0; j < jt; j++)
            {
                int tp = target.Parents[j];
                int parent = tp < 0 ? -1 : sourceIndex[tp];
                if (target.Names[j] == "LeftUpLeg")
                {
                    names.Add("src_LeftHipJoint");
                    parents.Add(parent);
                    targetOf.Add(-1);
                    parent = names.Count - 1;
                }

                sourceIndex[j] = names.Count;
                names.Add("src_" + target.Names[j]);
                parents.Add(parent);
                targetOf.Add(j);
                if (target.Names[j] == "LeftHand")
                {
                    names.Add("src_LeftFinger");
                    parents.Add(sourceIndex[j]);
                    targetOf.Add(-2);
                }
            }

            int js = names.Count;
            var frame = new QuaternionD[js];      // the source's reference global rotations (random frames)
            var position = new Vector3D[js];      // the source's reference global positions
            for (int s = 0; s < js; s++)
            {
                frame[s] = rng.Rotation();
                int t = targetOf[s];
                if (parents[s] < 0)
                {
                    position[s] = unit * Quaternions.Apply(yaw, tpose.GlobalPosition(0));
                }
                else if (t == -1)
                {
                    position[s] = position[parents[s]];   // zero-length, like CMU's hip joints
                }
                else
                {
                    Vector3D bone = t >= 0
                        ? tpose.GlobalPosition(t) - tpose.GlobalPosition(target.Parents[t])
                        : new Vector3D(8.0, 0.0, 0.0);    // the finger points further out along the left arm
                    position[s] = position[parents[s]] + rng.Uniform(0.7, 1.4) * unit * Quaternions.Apply(yaw, bone);
                }
            }

            // The LeftUpLeg's bone starts at the hips (through the zero-length hip joint).
            var offsets = new double[3 * js];
            var local = new double[4 * js];
            for (int s = 0; s < js; s++)
            {
                int p = parents[s];
                Vector3D o = p < 0 ? position[s] : Quaternions.Apply(Quaternions.Conjugate(frame[p]), position[s] - position[p]);
                o.Write(offsets, 3 * s);
                QuaternionD q = p < 0 ? frame[s] : Quaternions.Multiply(Quaternions.Conjugate(frame[p]), frame[s]);
                if (targetOf[s] >= 0 && Array.IndexOf(perturbed, target.Names[targetOf[s]]) >= 0)
                {
                    q = Quaternions.Multiply(q, Quaternions.FromAxisAngle(Normalized(rng.Vector(1.0)), rng.Uniform(10, 25) * Math.PI / 180.0));
                }

                Quaternions.Normalize(q).Write(local, 4 * s);
            }

            var skeleton = new Skeleton(names, parents, offsets);
            return (skeleton, new ReferencePose(skeleton, local, position[0]));
        }

        /// <summary>The JSON map from the model's joint names to the generated source's "src_" names.</summary>
        public static string SourceMapJson(Skeleton target)
        {
            var sb = new StringBuilder("{\n");
            for (int j = 0; j < target.JointCount; j++)
            {
                sb.Append("  \"").Append(target.Names[j]).Append("\": \"src_").Append(target.Names[j]).Append('"');
                sb.Append(j + 1 < target.JointCount ? ",\n" : "\n");
            }

            return sb.Append("}\n").ToString();
        }

        /// <summary>
        /// Smooth random motion around a reference pose: each joint's local rotation is the reference one
        /// times a rotation that wanders up to ~1 rad; the root walks. Joints in <paramref name="still"/> keep
        /// their reference rotation (CMU's hip joints are never keyed).
        /// </summary>
        public static MotionClip Motion(ReferencePose reference, int frames, double frameTime, int seed, double step, params string[] still)
        {
            var rng = new TestRandom(seed);
            Skeleton sk = reference.Skeleton;
            int j = sk.JointCount;
            var a = new Vector3D[j];
            var b = new Vector3D[j];
            for (int k = 0; k < j; k++)
            {
                a[k] = rng.Vector(0.9);
                b[k] = rng.Vector(0.9);
            }

            var positions = new double[frames * j * 3];
            var rotations = new double[frames * j * 4];
            Vector3D root = reference.RootPosition;
            for (int f = 0; f < frames; f++)
            {
                double t = f / (double)Math.Max(1, frames - 1);
                for (int k = 0; k < j; k++)
                {
                    QuaternionD rest = QuaternionD.Read(ToArray(reference.LocalRotations), 4 * k);
                    QuaternionD q = rest;
                    if (Array.IndexOf(still, sk.Names[k]) < 0)
                    {
                        Vector3D v = Math.Sin(2.0 * Math.PI * t) * a[k] + Math.Sin(Math.PI * t * 3.0 + 0.4) * b[k];
                        double angle = v.Length;
                        if (angle > 1e-12) q = Quaternions.Multiply(rest, Quaternions.FromAxisAngle((1.0 / angle) * v, angle));
                    }

                    Quaternions.Normalize(q).Write(rotations, (f * j + k) * 4);
                    Vector3D o = k == 0 ? root : Vector3D.Read(sk.OffsetSpan, 3 * k);
                    o.Write(positions, (f * j + k) * 3);
                }

                root = root + new Vector3D(step * rng.Uniform(-1, 1), 0.2 * step * rng.Uniform(-1, 1), step * rng.Uniform(-1, 1));
            }

            return new MotionClip(sk, frames, frameTime, positions, rotations);
        }

        /// <summary>
        /// The same motion on a skeleton whose zero pose is <paramref name="reference"/> (each joint's rest frame
        /// turned to the reference's global rotation): world positions are unchanged, so a tool that takes the
        /// zero pose as the reference (the CLI's default) sees the pose the generated rig means.
        /// </summary>
        public static MotionClip WithRestPose(MotionClip motion, ReferencePose reference)
        {
            Skeleton s = motion.Skeleton;
            int n = s.JointCount;
            var offsets = new double[3 * n];
            for (int j = 0; j < n; j++)
            {
                int p = s.Parents[j];
                Vector3D o = Vector3D.Read(s.OffsetSpan, 3 * j);
                (p < 0 ? o : Quaternions.Apply(reference.GlobalRotation(p), o)).Write(offsets, 3 * j);
            }

            var rest = new Skeleton(s.Names, s.Parents, offsets);
            var positions = new double[motion.LocalPositions.Length];
            var rotations = new double[motion.LocalRotations.Length];
            for (int f = 0; f < motion.FrameCount; f++)
            {
                Vector3D.Read(motion.LocalPositions, motion.PositionIndex(f, 0)).Write(positions, f * n * 3);
                for (int j = 0; j < n; j++)
                {
                    if (j > 0) Vector3D.Read(offsets, 3 * j).Write(positions, (f * n + j) * 3);
                    int p = s.Parents[j];
                    QuaternionD q = QuaternionD.Read(motion.LocalRotations, motion.RotationIndex(f, j));
                    QuaternionD left = p < 0 ? q : Quaternions.Multiply(reference.GlobalRotation(p), q);
                    Quaternions.Normalize(Quaternions.Multiply(left, Quaternions.Conjugate(reference.GlobalRotation(j)))).Write(rotations, (f * n + j) * 4);
                }
            }

            return new MotionClip(rest, motion.FrameCount, motion.FrameTime, positions, rotations);
        }

        /// <summary>Global positions of every frame (FK with every joint's local translation).</summary>
        public static double[] GlobalPositions(MotionClip clip)
        {
            int j = clip.Skeleton.JointCount;
            var positions = new double[clip.FrameCount * j * 3];
            var rotations = new double[clip.FrameCount * j * 4];
            ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, clip.FrameCount, clip.LocalPositions, clip.LocalRotations, positions, rotations);
            return positions;
        }

        /// <summary>Angle in radians between two rotations (0 for q and −q).</summary>
        public static double Angle(QuaternionD a, QuaternionD b)
        {
            a = Quaternions.Normalize(a);
            b = Quaternions.Normalize(b);
            if (Quaternions.Dot(a, b) < 0) b = b.Negated;
            // The 4-D angle φ between a and b is 2·atan2(|a − b|, |a + b|) (accurate near 0, unlike acos); the rotation angle is 2φ.
            double diff = new QuaternionD(a.W - b.W, a.X - b.X, a.Y - b.Y, a.Z - b.Z).Length;
            double sum = new QuaternionD(a.W + b.W, a.X + b.X, a.Y + b.Y, a.Z + b.Z).Length;
            return 4.0 * Math.Atan2(diff, sum);
        }

        /// <summary>Angle in radians between two non-zero vectors.</summary>
        public static double Angle(Vector3D a, Vector3D b) => Math.Atan2(Vector3D.Cross(a, b).Length, Vector3D.Dot(a, b));

        /// <summary>The CMU folder beside the repository (../shared/data/cmu); skips the test when absent.</summary>
        public static string RequireCmu()
        {
            string? root = TestEnvironment.RepositoryRoot;
            string? dir = root != null ? Path.GetFullPath(Path.Combine(root, "..", "shared", "data", "cmu")) : null;
            if (dir == null || !File.Exists(Path.Combine(dir, "02_04.bvh")))
            {
                Assert.Ignore($"CMU data absent: {dir ?? "../shared/data/cmu"}/02_04.bvh not found (place the cgspeed CMU BVH files in ../shared/data/cmu); skipping the data-dependent test.");
            }

            return dir!;
        }

        private static Vector3D Normalized(Vector3D v) => (1.0 / v.Length) * v;

        private static double[] ToArray(IReadOnlyList<double> values)
        {
            var a = new double[values.Count];
            for (int i = 0; i < a.Length; i++) a[i] = values[i];
            return a;
        }
    }
}
