using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Retargeting;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Characters
{
    /// <summary>
    /// Rigs that are not the model's, described as the Unity layer sees them (<see cref="CharacterRig"/>):
    /// HumanBodyBones names, other bone axes, a turned and scaled armature, left-handed. Real CMU and
    /// Poser skeletons and motion (../shared/data) go to the model and back.
    /// </summary>
    [TestFixture]
    public sealed class CharacterRigTests
    {
        public enum Source
        {
            Cmu,
            Poser,
        }

        private static UnityHumanoid Load(Source source)
        {
            if (source == Source.Cmu)
            {
                BvhAnimation cmu = BvhReader.Read(Path.Combine(RetargetFixtures.RequireCmu(), "02_04.bvh"));
                return UnityHumanoid.Cmu(cmu.Motion, seed: 11);
            }

            BvhAnimation poser = BvhReader.Read(Path.Combine(UnityHumanoid.RequireCmuMore(), "12_01.bvh"));
            return UnityHumanoid.Poser(poser.Motion, seed: 12);
        }

        [TestCase(Source.Cmu)]
        [TestCase(Source.Poser)]
        public void PosesRoundTripThroughTheModelAndBonesPointTheSameWay(Source source)
        {
            UnityHumanoid humanoid = Load(source);
            Skeleton model = RetargetFixtures.Lafan1();
            SkeletonPoseConverter map = humanoid.Rig.CreatePoseConverter(model, JointMap.UnityHumanoid);
            SkeletonMap retarget = map.Map;
            double[] deviation = BoneDirections.Deviations(retarget, ReferencePose.ModelTPose(model));
            for (int j = 0; j < deviation.Length; j++)
            {
                if (!double.IsNaN(deviation[j])) TestContext.WriteLine($"{source}: {model.Names[j]} reference {deviation[j] * 180 / Math.PI:F1}° from the model's T-pose");
            }

            TestContext.WriteLine($"{source}: synthesized {string.Join(", ", retarget.SynthesizedJoints)}; root scale {retarget.RootScale:F3}");
            if (source == Source.Poser) Assert.That(retarget.SynthesizedJoints, Is.EquivalentTo(new[] { "LeftToe", "RightToe", "Spine2" }));

            // The bones compared: aligned ones whose child's bone starts right below them in the rig (CMU's
            // Neck1 turns between Neck and Head on its own, so that bone's direction is the neck chain's, not Neck's).
            var compared = new List<(int Joint, int Child, int From, int To)>();
            for (int j = 1; j < model.JointCount; j++)
            {
                int c = OnlyChild(model, j);
                if (c < 0 || !retarget.AlignedBones[j] || retarget.IsSynthesized(c)) continue;
                int from = retarget.SourceJointOf(j), to = retarget.SourceJointOf(c);
                if (humanoid.Parents[to] != from) continue;
                compared.Add((j, c, from, to));
            }

            Assert.That(compared.Count, Is.GreaterThanOrEqualTo(source == Source.Cmu ? 14 : 12), "limb and spine bones compared");

            int n = humanoid.BoneCount;
            var root = new double[3];
            var rotations = new double[4 * n];
            var modelRoot = new double[3];
            var modelRotations = new double[4 * model.JointCount];
            var backRoot = new double[3];
            var back = new double[4 * n];
            var globalPositions = new double[3 * model.JointCount];
            var globalRotations = new double[4 * model.JointCount];
            double worstRotation = 0, worstRoot = 0, worstDirection = 0;
            int frames = 0;
            for (int f = 1; f < humanoid.FrameCount; f += 17)
            {
                humanoid.Pose(f, root, rotations);
                map.ToModel(root, rotations, modelRoot, modelRotations);
                map.ToCharacter(modelRoot, modelRotations, backRoot, back);
                for (int b = 0; b < n; b++) worstRotation = Math.Max(worstRotation, RetargetFixtures.Angle(QuaternionD.Read(rotations, 4 * b), QuaternionD.Read(back, 4 * b)));
                worstRoot = Math.Max(worstRoot, (Vector3D.Read(root, 0) - Vector3D.Read(backRoot, 0)).Length * humanoid.Armature.Scale);

                Vector3D[] character = humanoid.GlobalPositions(root, rotations);
                ForwardKinematics.ComputeFrame(model.ParentSpan, model.OffsetSpan, Vector3D.Read(modelRoot, 0), modelRotations, globalPositions, globalRotations);
                foreach (var bone in compared)
                {
                    Vector3D onModel = Handedness.PositionToUnity(Vector3D.Read(globalPositions, 3 * bone.Child) - Vector3D.Read(globalPositions, 3 * bone.Joint));
                    Vector3D onRig = character[bone.To] - character[bone.From];
                    worstDirection = Math.Max(worstDirection, RetargetFixtures.Angle(onModel, onRig));
                }

                frames++;
            }

            TestContext.WriteLine($"{source}: {frames} frames, {compared.Count} bones; worst round trip {worstRotation:E2} rad, root {worstRoot:E2} m; worst bone direction {worstDirection:E2} rad");
            Assert.That(worstRotation, Is.LessThan(1e-5), "rotation round trip (rad)");
            Assert.That(worstRoot, Is.LessThan(1e-5), "root position round trip (m)");
            Assert.That(worstDirection, Is.LessThan(1e-4), "bone world directions (rad)");
        }

        [TestCase(Source.Cmu)]
        [TestCase(Source.Poser)]
        public void AReferencePoseWithABoneTurned30DegreesIsRefusedNamingTheBone(Source source)
        {
            UnityHumanoid humanoid = Load(source);
            CharacterRig turned = TurnBone(humanoid, "LeftLowerArm", 30.0 + Baseline(humanoid, "LeftForeArm"));
            var error = Assert.Throws<JointMapException>(() => turned.CreatePoseConverter(RetargetFixtures.Lafan1(), JointMap.UnityHumanoid));
            TestContext.WriteLine(error!.Message);
            Assert.That(error.Message, Does.Contain("LeftLowerArm (LeftForeArm)"));
            Assert.That(error.Message, Does.Contain("25°"));
            Assert.That(error.Message, Does.Not.Contain("RightLowerArm"));
        }

        [Test]
        public void OnTheModelsOwnSkeletonTheLimitIs25Degrees()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            UnityHumanoid humanoid = UnityHumanoid.Model(model, UnityHumanoid.Blender, seed: 3);
            Assert.That(() => humanoid.Rig.CreatePoseConverter(model), Throws.Nothing);
            Assert.That(() => TurnBone(humanoid, "RightUpperLeg", 24).CreatePoseConverter(model), Throws.Nothing);
            var error = Assert.Throws<JointMapException>(() => TurnBone(humanoid, "RightUpperLeg", 26).CreatePoseConverter(model));
            Assert.That(error!.Message, Does.Contain("RightUpperLeg (RightUpLeg) 26°"));
        }

        [Test]
        public void ALafan1RigWithModelAxesMapsAsTheModelsOwnSkeletonDoes()
        {
            // The component's default (Generic, LaFAN1 names, reference from the model's axes) must convert
            // exactly as the name-for-name map of a character built from the model's skeleton did: only
            // handedness and units change.
            Skeleton model = RetargetFixtures.Lafan1();
            int n = model.JointCount;
            var positions = new double[3 * n];
            var bind = new double[4 * n];
            var random = new TestRandom(5);
            for (int j = 0; j < n; j++)
            {
                Handedness.PositionToUnity(0.01 * Vector3D.Read(model.OffsetSpan, 3 * j)).Write(positions, 3 * j);
                random.Rotation().Write(bind, 4 * j);   // a bind pose that is no T-pose at all
            }

            var rig = new CharacterRig("lafan1 rig", model.Names, model.Parents, positions, bind, RootFrame.Identity);
            SkeletonPoseConverter map = rig.WithModelTPoseByAxes().CreatePoseConverter(model, JointMap.Lafan1);
            var byName = new NamePoseConverter(model, 0.01, model.Names);
            var root = new[] { 0.2, 0.95, -0.4 };
            var rotations = new double[4 * n];
            for (int j = 0; j < n; j++) random.Rotation().Write(rotations, 4 * j);
            double[] a = new double[4 * n], b = new double[4 * n], ra = new double[3], rb = new double[3];
            map.ToModel(root, rotations, ra, a);
            byName.ToModel(root, rotations, rb, b);
            Assert.That(ra, Is.EqualTo(rb).Within(1e-9));
            for (int j = 0; j < n; j++) Assert.That(RetargetFixtures.Angle(QuaternionD.Read(a, 4 * j), QuaternionD.Read(b, 4 * j)), Is.LessThan(1e-9), model.Names[j]);
        }

        [Test]
        public void ARigWithoutAModelJointIsRefusedNamingIt()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            UnityHumanoid humanoid = UnityHumanoid.Model(model, RootFrame.Identity, seed: 4);
            CharacterRig rig = humanoid.Rig;
            var names = new List<string>(rig.BoneNames);
            names[names.IndexOf("LeftLowerLeg")] = "LeftKnee";
            var renamed = new CharacterRig("rig", names, rig.Parents, rig.LocalPositions, rig.ReferenceRotations, rig.Armature);
            var error = Assert.Throws<JointMapException>(() => renamed.CreatePoseConverter(model, JointMap.UnityHumanoid));
            Assert.That(error!.MissingJoints, Is.EqualTo(new[] { "LeftLeg" }));
            Assert.That(error.Message, Does.Contain("LeftLowerLeg"));
        }

        [Test]
        public void ARotationThatIsNotAQuaternionIsRefusedNamingTheBone()
        {
            var error = Assert.Throws<ArgumentException>(() => new CharacterRig("rig", new[] { "Hips", "Spine" }, new[] { -1, 0 }, new double[6], new double[] { 1, 0, 0, 0, 0, 0, 0, 0 }, RootFrame.Identity));
            Assert.That(error!.Message, Does.Contain("'Spine'"));
        }

        // A bone's reference rotation turned by extra degrees about an axis square to it (its local frame).
        private static CharacterRig TurnBone(UnityHumanoid humanoid, string bone, double degrees)
        {
            CharacterRig rig = humanoid.Rig;
            int b = humanoid.BoneIndex(bone);
            int child = -1;
            for (int k = 0; k < rig.Parents.Count; k++) if (rig.Parents[k] == b) child = k;
            Vector3D along = Vector3D.Read(ToArray(rig.LocalPositions), 3 * child);
            Vector3D axis = Vector3D.Cross(along, Math.Abs(along.Y) < 0.9 * along.Length ? Vector3D.UnitY : Vector3D.UnitX);
            axis = (1.0 / axis.Length) * axis;
            double[] rotations = ToArray(rig.ReferenceRotations);
            QuaternionD q = Quaternions.Multiply(QuaternionD.Read(rotations, 4 * b), Quaternions.FromAxisAngle(axis, degrees * Math.PI / 180));
            q.Write(rotations, 4 * b);
            return new CharacterRig(rig.Name, rig.BoneNames, rig.Parents, rig.LocalPositions, rotations, rig.Armature);
        }

        // How far the untouched reference already is, so that a turn adds to it rather than cancelling it.
        private static double Baseline(UnityHumanoid humanoid, string modelJoint)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            SkeletonMap map = humanoid.Rig.CreatePoseConverter(model, JointMap.UnityHumanoid, 90).Map;
            return BoneDirections.Deviations(map, ReferencePose.ModelTPose(model))[model.IndexOf(modelJoint)] * 180 / Math.PI;
        }

        private static int OnlyChild(Skeleton s, int joint)
        {
            int child = -1;
            for (int k = 1; k < s.JointCount; k++)
            {
                if (s.Parents[k] != joint) continue;
                if (child >= 0) return -1;
                child = k;
            }

            return child;
        }

        private static double[] ToArray(IReadOnlyList<double> values)
        {
            var a = new double[values.Count];
            for (int i = 0; i < a.Length; i++) a[i] = values[i];
            return a;
        }
    }
}
