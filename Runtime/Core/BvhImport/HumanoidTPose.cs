using System;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// The T-pose a humanoid avatar is built from: the file's rest pose (all rotations zero; for LaFAN1's
    /// names, whose rest pose has every bone along +X, the model's T-pose, <see cref="ReferencePose.Default"/>) with the
    /// limbs turned to the directions Unity's humanoid takes as its zero muscle pose — legs straight down,
    /// arms straight out sideways — as the avatar inspector's "Enforce T-Pose" does. A rest pose that is
    /// almost a T-pose is not good enough: CMU's legs are spread 20° at rest, and an avatar built from
    /// that would read a standing actor's legs as pressed 20° together and play them so on other characters.
    /// </summary>
    public static class HumanoidTPose
    {
        // Each limb bone and the bone its direction points to, with the side it points to (+1 left, -1 right, 0 down).
        private static readonly (string Bone, string Toward, int Side)[] Limbs =
        {
            ("LeftUpperLeg", "LeftLowerLeg", 0), ("LeftLowerLeg", "LeftFoot", 0),
            ("RightUpperLeg", "RightLowerLeg", 0), ("RightLowerLeg", "RightFoot", 0),
            ("LeftUpperArm", "LeftLowerArm", 1), ("LeftLowerArm", "LeftHand", 1),
            ("RightUpperArm", "RightLowerArm", -1), ("RightLowerArm", "RightHand", -1),
        };

        /// <summary>
        /// The local rotations (joints × 4, (w, x, y, z), model space) of the T-pose: the reference pose's, with
        /// the limb bones each turned by the shortest arc that points it where the T-pose wants it.
        /// </summary>
        /// <param name="skeleton">The file's skeleton.</param>
        /// <param name="mapping">Its humanoid mapping (<see cref="HumanoidMapping.Find"/>).</param>
        public static double[] LocalRotations(Skeleton skeleton, HumanoidMapping mapping)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (mapping == null) throw new ArgumentNullException(nameof(mapping));
            int count = skeleton.JointCount;
            var local = new double[4 * count];
            ReferencePose reference = ReferencePose.Default(skeleton);
            for (int i = 0; i < local.Length; i++) local[i] = reference.LocalRotations[i];
            Vector3D root = Vector3D.Read(skeleton.OffsetSpan, 0);
            Vector3D left = mapping.RestLeft(new ReferencePose(skeleton, local, root));
            Vector3D down = new Vector3D(0.0, -1.0, 0.0);
            foreach ((string bone, string toward, int side) in Limbs)
            {
                int b = mapping.JointIndexOf(bone);
                int c = mapping.JointIndexOf(toward);
                if (b < 0 || c < 0) continue;
                // FK again after every turn: each limb bone moves the ones below it.
                var pose = new ReferencePose(skeleton, local, root);
                Vector3D have = pose.GlobalPosition(c) - pose.GlobalPosition(b);
                if (have.Length < 1e-12) continue;
                Vector3D want = side == 0 ? down : side * left;
                QuaternionD turn = Quaternions.Between(have, want, Vector3D.UnitY);
                QuaternionD global = Quaternions.Multiply(turn, pose.GlobalRotation(b));
                int parent = skeleton.Parents[b];
                QuaternionD parentGlobal = parent >= 0 ? pose.GlobalRotation(parent) : QuaternionD.Identity;
                Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(parentGlobal), global)).Write(local, 4 * b);
            }

            return local;
        }
    }
}
