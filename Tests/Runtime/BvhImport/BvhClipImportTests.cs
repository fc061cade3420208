using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.BvhImport;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Bvh;
using DeltaInterpolator.Tests.Retargeting;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.BvhImport
{
    /// <summary>
    /// The <c>.bvh</c> importer's Core path (<see cref="BvhClipImport"/>) on the bundled CMU clip: the clip's
    /// curves, played through FK in Unity's space, must put every joint where the file's own FK does.
    /// </summary>
    public sealed class BvhClipImportTests
    {
        private const string Demo = "cmu_01_01_jumps_turn.bvh";

        private static string DemoPath()
        {
            string path = Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", Demo);
            if (!File.Exists(path)) Assert.Ignore($"{path} absent (Samples~ not in this copy); skipping.");
            return path;
        }

        [Test]
        public void CurvesPutEveryJointWhereTheFilesFkDoes()
        {
            string path = DemoPath();
            BvhImportResult import = BvhClipImport.ImportFile(path);
            (double relative, string worstAt) = MaxErrorInLegLengths(import, BvhReader.Read(path));
            TestContext.WriteLine($"{Demo}: {import.FrameCount} frames × {import.Joints.Count} joints; max position error {relative * import.LegLength:E3} m = {relative:E3} leg lengths ({worstAt}); leg length {import.LegLength:F4} m, {import.MetresPerUnit} m per unit");
            Assert.That(relative, Is.LessThan(1e-4), $"worst at {worstAt}");
        }

        /// <summary>
        /// Plays the clip's curves through FK in Unity's space (each key sampled, local transforms composed down
        /// the hierarchy from the prefab's root at the origin) and returns the largest distance from the file's
        /// own FK converted to Unity's space and metres, in leg lengths, with where it was.
        /// </summary>
        private static (double Relative, string Where) MaxErrorInLegLengths(BvhImportResult import, BvhAnimation bvh)
        {
            int frames = bvh.Motion.FrameCount;
            int jointCount = bvh.Skeleton.JointCount;
            var expected = new double[frames * jointCount * 3];
            ForwardKinematics.ComputeWithLocalPositions(bvh.Skeleton, frames, bvh.Motion.LocalPositions, bvh.Motion.LocalRotations, expected, new double[frames * jointCount * 4]);

            Dictionary<(string, string), ClipCurve> curves = import.Curves.ToDictionary(c => (c.Path, c.Property));
            var worldPositions = new Vector3D[jointCount];
            var worldRotations = new QuaternionD[jointCount];
            double worst = 0;
            string worstAt = "";
            for (int f = 0; f < frames; f++)
            {
                for (int j = 0; j < jointCount; j++)
                {
                    ImportedJoint joint = import.Joints[j];
                    QuaternionD local = Quaternions.Normalize(new QuaternionD(
                        Key(curves, joint.Path, "m_LocalRotation.w", f, import),
                        Key(curves, joint.Path, "m_LocalRotation.x", f, import),
                        Key(curves, joint.Path, "m_LocalRotation.y", f, import),
                        Key(curves, joint.Path, "m_LocalRotation.z", f, import)));
                    Vector3D position = joint.HasPositionCurves
                        ? new Vector3D(Key(curves, joint.Path, "m_LocalPosition.x", f, import), Key(curves, joint.Path, "m_LocalPosition.y", f, import), Key(curves, joint.Path, "m_LocalPosition.z", f, import))
                        : joint.RestPosition;
                    worldRotations[j] = joint.Parent < 0 ? local : Quaternions.Multiply(worldRotations[joint.Parent], local);
                    worldPositions[j] = joint.Parent < 0 ? position : worldPositions[joint.Parent] + Quaternions.Apply(worldRotations[joint.Parent], position);

                    Vector3D want = Handedness.PositionToUnity(import.MetresPerUnit * Vector3D.Read(expected, (f * jointCount + j) * 3));
                    double error = (worldPositions[j] - want).Length;
                    if (error > worst)
                    {
                        worst = error;
                        worstAt = $"{joint.Name} at frame {f}";
                    }
                }
            }

            return (worst / import.LegLength, worstAt);
        }

        private static double Key(Dictionary<(string, string), ClipCurve> curves, string path, string property, int frame, BvhImportResult import)
        {
            Assert.That(curves.TryGetValue((path, property), out ClipCurve? curve), Is.True, $"no curve {path}:{property}");
            Assert.That(curve!.Times[frame], Is.EqualTo(import.KeyTime(frame)));
            return curve.Values[frame];
        }

        [Test]
        public void ClipHasTheFilesFrameRateAndOneKeyPerFrame()
        {
            BvhImportResult import = BvhClipImport.ImportFile(DemoPath());
            Assert.That(import.FrameRate, Is.EqualTo(120.0), "Frame Time: .0083333 is 120 fps");
            Assert.That(import.FrameCount, Is.EqualTo(901));
            Assert.That(import.Name, Is.EqualTo("cmu_01_01_jumps_turn"));
            Assert.That(import.Curves.Count, Is.EqualTo(31 * 4 + 3), "rotation of every joint, position of the root");
            foreach (ClipCurve c in import.Curves)
            {
                Assert.That(c.KeyCount, Is.EqualTo(901), c.ToString());
                Assert.That(c.Times[900], Is.EqualTo((float)(900 / 120.0)), c.ToString());
            }
        }

        [Test]
        public void CmuUnitsBecomeMetres()
        {
            BvhImportResult import = BvhClipImport.ImportFile(DemoPath());
            Assert.That(import.MetresPerUnit, Is.EqualTo(BvhUnitScale.CmuUnit));
            Assert.That(import.LegLength, Is.InRange(0.8, 1.0), "a person's leg, metres");
            Assert.That(BvhClipImport.ImportFile(DemoPath(), 0.01).MetresPerUnit, Is.EqualTo(0.01), "a given unit wins");
        }

        [Test]
        public void MotionBuilderNamesMapOntoTheHumanoid()
        {
            HumanoidMapping? humanoid = BvhClipImport.ImportFile(DemoPath()).Humanoid;
            Assert.That(humanoid, Is.Not.Null);
            Assert.That(humanoid!.MapName, Is.EqualTo("cmu"));
            var expected = new Dictionary<string, string>
            {
                ["Hips"] = "Hips",
                ["LeftUpperLeg"] = "LeftUpLeg", ["LeftLowerLeg"] = "LeftLeg", ["LeftFoot"] = "LeftFoot", ["LeftToes"] = "LeftToeBase",
                ["RightUpperLeg"] = "RightUpLeg", ["RightLowerLeg"] = "RightLeg", ["RightFoot"] = "RightFoot", ["RightToes"] = "RightToeBase",
                // LowerBack sits on the hips and the shoulders on the upper spine (zero-length bones Unity refuses):
                // the spine moves up one joint, the chest takes Spine1, the shoulders are left out.
                ["Spine"] = "Spine", ["Chest"] = "Spine1", ["Neck"] = "Neck1", ["Head"] = "Head",
                ["LeftUpperArm"] = "LeftArm", ["LeftLowerArm"] = "LeftForeArm", ["LeftHand"] = "LeftHand",
                ["RightUpperArm"] = "RightArm", ["RightLowerArm"] = "RightForeArm", ["RightHand"] = "RightHand",
            };
            Assert.That(humanoid.Bones.ToDictionary(b => b.Key, b => b.Value), Is.EquivalentTo(expected));
        }

        [Test]
        public void AvatarTPoseHasStraightLimbsAndStandsOnTheGround()
        {
            BvhImportResult import = BvhClipImport.ImportFile(DemoPath());
            Vector3D[] rest = RestPositions(import);
            Assert.That(rest.Min(p => p.Y), Is.EqualTo(0.0).Within(1e-12), "the lowest joint on the ground");
            // CMU faces +Z at rest; Unity is left-handed, so the character's left is −X.
            AssertDirection(import, rest, "LeftUpLeg", "LeftLeg", new Vector3D(0, -1, 0));
            AssertDirection(import, rest, "LeftLeg", "LeftFoot", new Vector3D(0, -1, 0));
            AssertDirection(import, rest, "RightUpLeg", "RightLeg", new Vector3D(0, -1, 0));
            AssertDirection(import, rest, "RightLeg", "RightFoot", new Vector3D(0, -1, 0));
            AssertDirection(import, rest, "LeftArm", "LeftForeArm", new Vector3D(-1, 0, 0));
            AssertDirection(import, rest, "LeftForeArm", "LeftHand", new Vector3D(-1, 0, 0));
            AssertDirection(import, rest, "RightArm", "RightForeArm", new Vector3D(1, 0, 0));
            AssertDirection(import, rest, "RightForeArm", "RightHand", new Vector3D(1, 0, 0));
        }

        private static Vector3D[] RestPositions(BvhImportResult import)
        {
            int n = import.Joints.Count;
            var positions = new Vector3D[n];
            var rotations = new QuaternionD[n];
            for (int j = 0; j < n; j++)
            {
                ImportedJoint joint = import.Joints[j];
                rotations[j] = joint.Parent < 0 ? joint.RestRotation : Quaternions.Multiply(rotations[joint.Parent], joint.RestRotation);
                positions[j] = joint.Parent < 0 ? joint.RestPosition : positions[joint.Parent] + Quaternions.Apply(rotations[joint.Parent], joint.RestPosition);
            }

            return positions;
        }

        private static void AssertDirection(BvhImportResult import, Vector3D[] rest, string from, string to, Vector3D want)
        {
            int a = import.Joints.ToList().FindIndex(j => j.Name == from);
            int b = import.Joints.ToList().FindIndex(j => j.Name == to);
            Vector3D d = rest[b] - rest[a];
            Assert.That(Vector3D.Dot((1.0 / d.Length) * d, want), Is.GreaterThan(1 - 1e-9), $"{from} → {to} points {d}, expected along {want}");
        }

        [Test]
        public void Lafan1NamesImportInCentimetresWithTheModelsTPose()
        {
            // LaFAN1's rest pose has every bone along +X: the unit and the T-pose come from the model's T-pose instead.
            Skeleton skeleton = RetargetFixtures.Lafan1();
            MotionClip motion = RetargetFixtures.Motion(ReferencePose.ModelTPose(skeleton), 60, 1.0 / 30.0, seed: 17, step: 2.0);
            BvhAnimation bvh = BvhAnimation.ForSkeleton(motion, "lafan1");
            var text = new StringWriter();
            BvhWriter.Write(bvh, text);
            byte[] data = Encoding.UTF8.GetBytes(text.ToString());
            BvhImportResult import = BvhClipImport.Import(data, "Assets/walk1_subject1.bvh");

            Assert.That(import.MetresPerUnit, Is.EqualTo(0.01));
            Assert.That(import.Humanoid!.MapName, Is.EqualTo("lafan1"));
            Assert.That(import.Humanoid.Bones.Count, Is.EqualTo(22), "every body bone, the upper chest and shoulders included");
            Assert.That(import.Humanoid.JointOf("UpperChest"), Is.EqualTo("Spine2"));
            Vector3D[] rest = RestPositions(import);
            AssertDirection(import, rest, "Spine", "Spine1", new Vector3D(0, 1, 0));
            AssertDirection(import, rest, "LeftUpLeg", "LeftLeg", new Vector3D(0, -1, 0));
            AssertDirection(import, rest, "LeftArm", "LeftForeArm", new Vector3D(-1, 0, 0));
            AssertDirection(import, rest, "RightArm", "RightForeArm", new Vector3D(1, 0, 0));
            (double relative, string worstAt) = MaxErrorInLegLengths(import, BvhReader.Parse(data, "lafan1"));
            Assert.That(relative, Is.LessThan(1e-4), $"worst at {worstAt}");
        }

        [Test]
        public void TwoImportsGiveTheSameIdsNamesAndCurves()
        {
            byte[] data = File.ReadAllBytes(DemoPath());
            BvhImportResult first = BvhClipImport.Import(data, "Assets/Mocap/" + Demo);
            BvhImportResult second = BvhClipImport.Import(data, "Assets/Mocap/" + Demo);
            Assert.That(first.SubAssetIds, Is.EqualTo(second.SubAssetIds));
            Assert.That(first.SubAssetIds, Is.EqualTo(new[] { "figure", "clip", "avatar" }));
            Assert.That(first.SubAssetIds.Distinct().Count(), Is.EqualTo(first.SubAssetIds.Count));
            Assert.That(BvhClipImport.Import(data, "Assets/Elsewhere/renamed.bvh").SubAssetIds, Is.EqualTo(first.SubAssetIds), "ids do not depend on the file's name or place");
            Assert.That(first.Joints.Select(j => j.Path), Is.EqualTo(second.Joints.Select(j => j.Path)));
            Assert.That(first.Figure.Select(b => b.Name), Is.EqualTo(second.Figure.Select(b => b.Name)));
            Assert.That(first.LocalRotations, Is.EqualTo(second.LocalRotations));
            var names = new HashSet<string>(first.Joints.Select(j => j.Name)) { first.RootName };
            foreach (FigureBone bone in first.Figure) Assert.That(names.Add(bone.Name), Is.True, $"{bone.Name} is not unique in the prefab");
        }

        [Test]
        public void RotationKeysStayInOneHemisphere()
        {
            BvhImportResult import = BvhClipImport.ImportFile(DemoPath());
            int n = import.Joints.Count;
            for (int f = 1; f < import.FrameCount; f++)
            {
                for (int j = 0; j < n; j++)
                {
                    double dot = 0;
                    for (int c = 0; c < 4; c++) dot += import.LocalRotations[(f * n + j) * 4 + c] * import.LocalRotations[((f - 1) * n + j) * 4 + c];
                    Assert.That(dot, Is.GreaterThanOrEqualTo(0.0), $"{import.Joints[j].Name} at frame {f}");
                }
            }
        }

        [Test]
        public void UnreadableBvhNamesTheFile()
        {
            byte[] truncated = Encoding.UTF8.GetBytes("HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n");
            var e = Assert.Throws<BvhFormatException>(() => BvhClipImport.Import(truncated, "Assets/Mocap/broken.bvh"));
            Assert.That(e!.Message, Does.StartWith("Assets/Mocap/broken.bvh:"));
            Assert.Throws<InputPathException>(() => BvhClipImport.ImportFile(Path.Combine(Path.GetTempPath(), "no-such-file-" + Guid.NewGuid() + ".bvh")));
        }

        [Test]
        public void UnitOfALeglessSkeletonMustBeGiven()
        {
            // The two-joint sample has its only child above the root: there is no leg to measure.
            byte[] data = Encoding.UTF8.GetBytes(BvhSamples.TwoJoints);
            var e = Assert.Throws<DataFormatException>(() => BvhClipImport.Import(data, "Assets/spine.bvh"));
            Assert.That(e!.Message, Does.StartWith("Assets/spine.bvh:"));
            Assert.That(e.Message, Does.Contain("Metres Per Unit"));
            BvhImportResult import = BvhClipImport.Import(data, "Assets/spine.bvh", 0.01);
            Assert.That(import.Humanoid, Is.Null, "names of no built-in map: a generic avatar");
            Assert.That(import.FrameRate, Is.EqualTo(30.0), "Frame Time: 0.033333 is 30 fps");
        }

        [TestCase(0.0083333, 120.0)]
        [TestCase(1.0 / 30.0, 30.0)]
        [TestCase(0.04, 25.0)]
        [TestCase(0.3, 1.0 / 0.3)]
        public void FrameRateIsWholeWhenTheFrameTimeWasRounded(double frameTime, double rate)
        {
            Assert.That(BvhClipImport.FrameRate(frameTime), Is.EqualTo(rate).Within(1e-12));
        }
    }
}
