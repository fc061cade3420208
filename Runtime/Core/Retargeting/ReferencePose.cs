using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// The pose in which a skeleton's bones are compared with another skeleton's: its local rotations
    /// (w, x, y, z) and root position, with the global rotations and positions FK gives. Retargeting
    /// aligns the two skeletons' reference poses (<see cref="SkeletonMap"/>), never their zero poses: at
    /// zero rotations LaFAN1's bones all point along +X, CMU's legs are spread 20°, a Unity rig's zero
    /// pose is whatever its modeller left. Use <see cref="ModelTPose"/> for the model's skeleton and
    /// <see cref="Zero"/> or <see cref="FromFrame"/> (e.g. CMU's T-pose at frame 0) for a source.
    /// </summary>
    public sealed class ReferencePose
    {
        private readonly double[] _local;
        private readonly double[] _globalRotations;
        private readonly double[] _globalPositions;

        /// <summary>Creates a reference pose (arrays copied).</summary>
        /// <param name="skeleton">The skeleton (its offsets place the joints).</param>
        /// <param name="localRotations">joints × 4 local rotations (w, x, y, z); the root's is global.</param>
        /// <param name="rootPosition">The root's position (only heights relative to it matter).</param>
        public ReferencePose(Skeleton skeleton, IReadOnlyList<double> localRotations, Vector3D rootPosition)
        {
            Skeleton = skeleton ?? throw new ArgumentNullException(nameof(skeleton));
            int j = skeleton.JointCount;
            if (localRotations == null || localRotations.Count != 4 * j)
            {
                throw new ArgumentException($"local rotations must hold joints × 4 = {4 * j} values", nameof(localRotations));
            }

            _local = new double[4 * j];
            for (int k = 0; k < j; k++)
            {
                QuaternionD q = Quaternions.Normalize(new QuaternionD(localRotations[4 * k], localRotations[4 * k + 1], localRotations[4 * k + 2], localRotations[4 * k + 3]));
                q.Write(_local, 4 * k);
            }

            RootPosition = rootPosition;
            _globalRotations = new double[4 * j];
            _globalPositions = new double[3 * j];
            ForwardKinematics.ComputeFrame(skeleton.ParentSpan, skeleton.OffsetSpan, rootPosition, _local, _globalPositions, _globalRotations);
        }

        /// <summary>The skeleton.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>joints × 4 local rotations (w, x, y, z).</summary>
        public IReadOnlyList<double> LocalRotations => _local;

        /// <summary>The root's position.</summary>
        public Vector3D RootPosition { get; }

        /// <summary>Joint <paramref name="joint"/>'s global rotation.</summary>
        public QuaternionD GlobalRotation(int joint) => QuaternionD.Read(_globalRotations, 4 * joint);

        /// <summary>Joint <paramref name="joint"/>'s global position.</summary>
        public Vector3D GlobalPosition(int joint) => Vector3D.Read(_globalPositions, 3 * joint);

        /// <summary>All rotations zero (identity), the root at its rest offset: a BVH skeleton's rest pose.</summary>
        public static ReferencePose Zero(Skeleton skeleton)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            var q = new double[4 * skeleton.JointCount];
            for (int k = 0; k < skeleton.JointCount; k++) q[4 * k] = 1.0;
            return new ReferencePose(skeleton, q, Vector3D.Read(skeleton.OffsetSpan, 0));
        }

        /// <summary>
        /// The reference pose to use when the user names none: <see cref="ModelTPose"/> for a skeleton with
        /// all of LaFAN1's joint names (its bones follow LaFAN1's local axes, so the model's T-pose by axes
        /// fits it and LaFAN1 motion reaches the model unchanged), otherwise its zero pose.
        /// </summary>
        public static ReferencePose Default(Skeleton skeleton)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            foreach (string name in JointMap.Lafan1.TargetJoints)
            {
                if (skeleton.IndexOf(name) < 0) return Zero(skeleton);
            }

            return ModelTPose(skeleton);
        }

        /// <summary>The pose of frame <paramref name="frame"/> of a clip (e.g. CMU's T-pose at frame 0).</summary>
        /// <exception cref="ArgumentOutOfRangeException">The clip has no such frame.</exception>
        public static ReferencePose FromFrame(MotionClip clip, int frame)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (frame < 0 || frame >= clip.FrameCount)
            {
                throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame} is not in the clip (0..{clip.FrameCount - 1})");
            }

            int j = clip.Skeleton.JointCount;
            var q = new double[4 * j];
            Array.Copy(clip.LocalRotations, clip.RotationIndex(frame, 0), q, 0, 4 * j);
            return new ReferencePose(clip.Skeleton, q, Vector3D.Read(clip.LocalPositions, clip.PositionIndex(frame, 0)));
        }

        /// <summary>
        /// A pose given by where each joint's local axes point in the world: local +X along
        /// <c>boneAxis</c> and local +Z as close to <c>twistAxis</c> as is perpendicular to it. Joints not
        /// named keep their parent's global rotation. The root is placed so that the lowest joint stands
        /// at height 0.
        /// </summary>
        /// <param name="skeleton">The skeleton.</param>
        /// <param name="axes">Joint name → (world direction of local +X, world direction of local +Z).</param>
        public static ReferencePose FromGlobalAxes(Skeleton skeleton, IReadOnlyDictionary<string, (Vector3D BoneAxis, Vector3D TwistAxis)> axes)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (axes == null) throw new ArgumentNullException(nameof(axes));
            int count = skeleton.JointCount;
            var global = new QuaternionD[count];
            var local = new double[4 * count];
            for (int j = 0; j < count; j++)
            {
                int parent = skeleton.Parents[j];
                if (axes.TryGetValue(skeleton.Names[j], out (Vector3D BoneAxis, Vector3D TwistAxis) a))
                {
                    global[j] = FromAxes(a.BoneAxis, a.TwistAxis);
                }
                else
                {
                    global[j] = parent >= 0 ? global[parent] : QuaternionD.Identity;
                }

                QuaternionD q = parent >= 0 ? Quaternions.Multiply(Quaternions.Conjugate(global[parent]), global[j]) : global[j];
                q.Write(local, 4 * j);
            }

            var atOrigin = new ReferencePose(skeleton, local, Vector3D.Zero);
            double lowest = 0.0;
            for (int j = 0; j < count; j++) lowest = Math.Min(lowest, atOrigin.GlobalPosition(j).Y);
            return new ReferencePose(skeleton, local, new Vector3D(0.0, -lowest, 0.0));
        }

        /// <summary>
        /// The model's reference pose: a T-pose of LaFAN1's 22 joints, facing +Z with the character's left
        /// along +X and Y up, feet on the ground. Bone directions: legs straight down, feet 30° below
        /// forward, toes forward, spine, neck and head straight up, shoulders and arms straight out
        /// sideways. Twist (where each joint's local +Z points) is as LaFAN1's actors carry it when they
        /// stand and walk (measured on obstacles1_subject1 and dance1_subject1 with the root's yaw removed),
        /// carried into the T-pose: hips and spine +Z to the character's left, legs and feet to its right,
        /// the left clavicle and arm +Z up and the right ones down (the arms raised sideways from hanging).
        /// Measured on CMU 02_04 retargeted with it, the median twist of each local rotation about its
        /// bone (X) lies within 10° of LaFAN1's for every joint but the hands (about 50° apart), so the
        /// model sees local rotations like those it was trained on. Joints of other names keep their
        /// parent's global rotation.
        /// </summary>
        public static ReferencePose ModelTPose(Skeleton skeleton)
        {
            Vector3D up = Vector3D.UnitY, down = new Vector3D(0, -1, 0);
            Vector3D left = Vector3D.UnitX, right = new Vector3D(-1, 0, 0);
            Vector3D forward = Vector3D.UnitZ, backward = new Vector3D(0, 0, -1);
            Vector3D foot = new Vector3D(0.0, -0.5, Math.Sqrt(0.75));
            var axes = new Dictionary<string, (Vector3D, Vector3D)>(StringComparer.Ordinal)
            {
                ["Hips"] = (up, left),
                ["LeftUpLeg"] = (down, right), ["LeftLeg"] = (down, right), ["LeftFoot"] = (foot, right), ["LeftToe"] = (forward, right),
                ["RightUpLeg"] = (down, right), ["RightLeg"] = (down, right), ["RightFoot"] = (foot, right), ["RightToe"] = (forward, right),
                ["Spine"] = (up, left), ["Spine1"] = (up, left), ["Spine2"] = (up, left), ["Neck"] = (up, left), ["Head"] = (up, left),
                ["LeftShoulder"] = (left, up), ["LeftArm"] = (left, up), ["LeftForeArm"] = (left, up), ["LeftHand"] = (left, up),
                ["RightShoulder"] = (right, down), ["RightArm"] = (right, down), ["RightForeArm"] = (right, down), ["RightHand"] = (right, down),
            };
            return FromGlobalAxes(skeleton, axes);
        }

        internal static QuaternionD FromAxes(Vector3D xAxis, Vector3D zHint)
        {
            Vector3D x = (1.0 / xAxis.Length) * xAxis;
            Vector3D z = zHint - Vector3D.Dot(zHint, x) * x;
            double zl = z.Length;
            if (zl < 1e-9) throw new ArgumentException("the twist axis is parallel to the bone axis", nameof(zHint));
            z = (1.0 / zl) * z;
            Vector3D y = Vector3D.Cross(z, x);
            // Columns are the images of the local axes.
            return Quaternions.FromMatrix(new Matrix3x3D(x.X, y.X, z.X, x.Y, y.Y, z.Y, x.Z, y.Z, z.Z));
        }
    }
}
