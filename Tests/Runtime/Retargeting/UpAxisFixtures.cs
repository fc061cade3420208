using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>
    /// Rigs and walks made in the tests for the up-axis and humanoid-plausibility rules: a rig whose rest
    /// pose stands (Y up) in the model's T-pose, a walk authored on it, and the same walk written as a Z-up
    /// file would hold it (the skeleton in a Z-up world, or a Z-up rest skeleton), plus a four-legged rig.
    /// Joints are named "src_" + the model's names (<see cref="RetargetFixtures.SourceMapJson"/> maps them).
    /// </summary>
    public static class UpAxisFixtures
    {
        /// <summary>Y up → Z up: +90° about X (the inverse of <see cref="UpAxisDetection.ToYUp"/> for Z).</summary>
        public static QuaternionD YToZ => Quaternions.Conjugate(UpAxisDetection.ToYUp(UpAxis.Z));

        /// <summary>The map from the model's names to the fixtures' "src_" names.</summary>
        public static JointMap Map(Skeleton model) => JointMap.FromJson(RetargetFixtures.SourceMapJson(model), "src-map.json");

        /// <summary>A rig of the model's joints whose zero pose is <paramref name="positions"/> (global joint positions), turned by <paramref name="turn"/>.</summary>
        public static Skeleton FromPositions(Skeleton model, IReadOnlyList<Vector3D> positions, QuaternionD turn)
        {
            var names = new string[model.JointCount];
            var offsets = new double[3 * model.JointCount];
            for (int j = 0; j < model.JointCount; j++)
            {
                names[j] = "src_" + model.Names[j];
                int p = model.Parents[j];
                Vector3D offset = p < 0 ? positions[j] : positions[j] - positions[p];
                Quaternions.Apply(turn, offset).Write(offsets, 3 * j);
            }

            return new Skeleton(names, model.Parents, offsets);
        }

        /// <summary>A rig whose zero pose is the model's T-pose (Y up, feet on the ground), turned by <paramref name="turn"/>.</summary>
        public static Skeleton Standing(Skeleton model, QuaternionD turn)
        {
            ReferencePose tpose = ReferencePose.ModelTPose(model);
            var positions = new Vector3D[model.JointCount];
            for (int j = 0; j < positions.Length; j++) positions[j] = tpose.GlobalPosition(j);
            return FromPositions(model, positions, turn);
        }

        /// <summary>The T-pose rig with the arms hanging down at the sides (a common rest pose).</summary>
        public static Skeleton ArmsDown(Skeleton model)
        {
            ReferencePose tpose = ReferencePose.ModelTPose(model);
            var positions = new Vector3D[model.JointCount];
            for (int j = 0; j < positions.Length; j++) positions[j] = tpose.GlobalPosition(j);
            foreach (string side in new[] { "Left", "Right" })
            {
                int arm = model.IndexOf(side + "Arm"), fore = model.IndexOf(side + "ForeArm"), hand = model.IndexOf(side + "Hand");
                double upper = (positions[fore] - positions[arm]).Length, lower = (positions[hand] - positions[fore]).Length;
                positions[fore] = positions[arm] + new Vector3D(0, -upper, 0);
                positions[hand] = positions[fore] + new Vector3D(0, -lower, 0);
            }

            return FromPositions(model, positions, QuaternionD.Identity);
        }

        /// <summary>A four-legged rig named like a humanoid: spine and neck along +Z, hind legs under the hips, arms as front legs.</summary>
        public static Skeleton Quadruped(Skeleton model)
        {
            var at = new Dictionary<string, Vector3D>
            {
                ["Hips"] = new Vector3D(0, 60, 0),
                ["LeftUpLeg"] = new Vector3D(10, 58, 0), ["LeftLeg"] = new Vector3D(10, 30, 2), ["LeftFoot"] = new Vector3D(10, 3, 0), ["LeftToe"] = new Vector3D(10, 0, 8),
                ["RightUpLeg"] = new Vector3D(-10, 58, 0), ["RightLeg"] = new Vector3D(-10, 30, 2), ["RightFoot"] = new Vector3D(-10, 3, 0), ["RightToe"] = new Vector3D(-10, 0, 8),
                ["Spine"] = new Vector3D(0, 61, 12), ["Spine1"] = new Vector3D(0, 62, 26), ["Spine2"] = new Vector3D(0, 62, 40), ["Neck"] = new Vector3D(0, 64, 58), ["Head"] = new Vector3D(0, 70, 72),
                ["LeftShoulder"] = new Vector3D(5, 60, 48), ["LeftArm"] = new Vector3D(10, 56, 50), ["LeftForeArm"] = new Vector3D(10, 30, 50), ["LeftHand"] = new Vector3D(10, 3, 51),
                ["RightShoulder"] = new Vector3D(-5, 60, 48), ["RightArm"] = new Vector3D(-10, 56, 50), ["RightForeArm"] = new Vector3D(-10, 30, 50), ["RightHand"] = new Vector3D(-10, 3, 51),
            };
            var positions = new Vector3D[model.JointCount];
            for (int j = 0; j < positions.Length; j++) positions[j] = at[model.Names[j]];
            return FromPositions(model, positions, QuaternionD.Identity);
        }

        /// <summary>
        /// A walk authored Y up on <paramref name="rig"/> (a <see cref="Standing"/> rig, zero pose = T-pose):
        /// the root travels and turns, the legs swing and the knees bend; frame 0 stands (legs straight).
        /// </summary>
        public static MotionClip Walk(Skeleton rig, int frames, double frameTime)
        {
            int n = rig.JointCount;
            var positions = new double[frames * n * 3];
            var rotations = new double[frames * n * 4];
            Vector3D rest = Vector3D.Read(rig.OffsetSpan, 0);
            for (int f = 0; f < frames; f++)
            {
                double t = f * frameTime, phase = 2 * Math.PI * 1.1 * t, swing = Math.Sin(phase);
                for (int j = 0; j < n; j++)
                {
                    Vector3D.Read(rig.OffsetSpan, 3 * j).Write(positions, (f * n + j) * 3);
                    QuaternionD.Identity.Write(rotations, (f * n + j) * 4);
                }

                new Vector3D(45 * t, rest.Y + 2 * Math.Sin(2 * phase), 110 * t).Write(positions, f * n * 3);
                Set(rotations, f, n, 0, Quaternions.FromAxisAngle(Vector3D.UnitY, 0.3 * t));
                Set(rotations, f, n, rig.IndexOf("src_LeftUpLeg"), Quaternions.FromAxisAngle(Vector3D.UnitX, 0.35 * swing));
                Set(rotations, f, n, rig.IndexOf("src_RightUpLeg"), Quaternions.FromAxisAngle(Vector3D.UnitX, -0.35 * swing));
                Set(rotations, f, n, rig.IndexOf("src_LeftLeg"), Quaternions.FromAxisAngle(Vector3D.UnitX, 0.5 * Math.Max(0, swing)));
                Set(rotations, f, n, rig.IndexOf("src_RightLeg"), Quaternions.FromAxisAngle(Vector3D.UnitX, 0.5 * Math.Max(0, -swing)));
                Set(rotations, f, n, rig.IndexOf("src_LeftArm"), Quaternions.FromAxisAngle(Vector3D.UnitZ, -0.9 + 0.2 * swing));
                Set(rotations, f, n, rig.IndexOf("src_RightArm"), Quaternions.FromAxisAngle(Vector3D.UnitZ, 0.9 + 0.2 * swing));
                Set(rotations, f, n, rig.IndexOf("src_Spine1"), Quaternions.FromAxisAngle(Vector3D.UnitY, 0.1 * swing));
            }

            return new MotionClip(rig, frames, frameTime, positions, rotations);
        }

        /// <summary>The same walk with its world turned Z up: the root's rotation and position turned by <see cref="YToZ"/>.</summary>
        public static MotionClip InZUpWorld(MotionClip walk)
        {
            double[] positions = (double[])walk.LocalPositions.Clone(), rotations = (double[])walk.LocalRotations.Clone();
            int n = walk.Skeleton.JointCount;
            for (int f = 0; f < walk.FrameCount; f++)
            {
                Quaternions.Apply(YToZ, Vector3D.Read(positions, f * n * 3)).Write(positions, f * n * 3);
                Quaternions.Normalize(Quaternions.Multiply(YToZ, QuaternionD.Read(rotations, f * n * 4))).Write(rotations, f * n * 4);
            }

            return new MotionClip(walk.Skeleton, walk.FrameCount, walk.FrameTime, positions, rotations);
        }

        /// <summary>The same walk on a Z-up rest skeleton: every offset, root position and rotation expressed in Z-up axes.</summary>
        public static MotionClip OnZUpSkeleton(MotionClip walk)
        {
            Skeleton y = walk.Skeleton;
            int n = y.JointCount;
            var offsets = new double[3 * n];
            for (int j = 0; j < n; j++) Quaternions.Apply(YToZ, Vector3D.Read(y.OffsetSpan, 3 * j)).Write(offsets, 3 * j);
            var z = new Skeleton(y.Names, y.Parents, offsets);
            var positions = new double[walk.LocalPositions.Length];
            var rotations = new double[walk.LocalRotations.Length];
            QuaternionD back = Quaternions.Conjugate(YToZ);
            for (int f = 0; f < walk.FrameCount; f++)
            {
                for (int j = 0; j < n; j++)
                {
                    Quaternions.Apply(YToZ, Vector3D.Read(walk.LocalPositions, (f * n + j) * 3)).Write(positions, (f * n + j) * 3);
                    QuaternionD q = QuaternionD.Read(walk.LocalRotations, (f * n + j) * 4);
                    Quaternions.Normalize(Quaternions.Multiply(YToZ, Quaternions.Multiply(q, back))).Write(rotations, (f * n + j) * 4);
                }
            }

            return new MotionClip(z, walk.FrameCount, walk.FrameTime, positions, rotations);
        }

        private static void Set(double[] rotations, int frame, int joints, int joint, QuaternionD q) => q.Write(rotations, (frame * joints + joint) * 4);
    }
}
