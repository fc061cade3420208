using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>
    /// Model joints a rig lacks (Poser toes and Spine2, a rig without an upper chest or neck) are synthesized:
    /// rigid children of their parents at the aligned reference pose's offset; everything else still maps exactly.
    /// </summary>
    public sealed class JointSynthesisTests
    {
        private static readonly string[] Lacking = { "LeftToe", "RightToe", "Spine2" };

        private static (SkeletonMap Map, MotionClip Source) Build(int seed)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            (Skeleton skeleton, ReferencePose reference) = RetargetFixtures.Source(model, seed, 0.5, 30.0, "LeftArm", "RightLeg");
            string json = RetargetFixtures.SourceMapJson(model);
            foreach (string name in Lacking) json = json.Replace($"\"{name}\": \"src_{name}\"", $"\"{name}\": null");
            JointMap map = JointMap.FromJson(json, "lacking.json");
            SkeletonMap m = SkeletonMap.Create(reference, ReferencePose.ModelTPose(model), map, "rig without toes and upper chest");
            MotionClip motion = RetargetFixtures.Motion(reference, 40, 1.0 / 120.0, seed + 1, 3.0, "src_LeftHipJoint");
            return (m, motion);
        }

        [TestCase(11)]
        [TestCase(12)]
        public void SynthesizedJointsAreRigidChildrenAndTheRestMapsExactly(int seed)
        {
            (SkeletonMap map, MotionClip source) = Build(seed);
            Assert.That(map.SynthesizedJoints, Is.EqualTo(new[] { "LeftToe", "RightToe", "Spine2" }));
            MotionClip onModel = map.ToTarget(source);
            Skeleton target = map.Target;
            foreach (string name in Lacking)
            {
                int j = target.IndexOf(name);
                Assert.That(map.IsSynthesized(j), Is.True);
                var reference = new QuaternionD(map.TargetReference.LocalRotations[4 * j], map.TargetReference.LocalRotations[4 * j + 1],
                    map.TargetReference.LocalRotations[4 * j + 2], map.TargetReference.LocalRotations[4 * j + 3]);
                for (int f = 0; f < onModel.FrameCount; f++)
                {
                    Assert.That(RetargetFixtures.Angle(reference, QuaternionD.Read(onModel.LocalRotations, onModel.RotationIndex(f, j))), Is.LessThan(1e-9), $"{name}, frame {f}");
                }
            }

            // Bones between mapped joints (the neck hangs below the made-up Spine2) point like the source's on every frame.
            double[] sg = RetargetFixtures.GlobalPositions(source), tg = RetargetFixtures.GlobalPositions(onModel);
            int js = source.Skeleton.JointCount, jt = target.JointCount;
            foreach ((string a, string b) in new[] { ("Neck", "Head"), ("LeftUpLeg", "LeftLeg"), ("RightArm", "RightForeArm") })
            {
                int ta = target.IndexOf(a), tb = target.IndexOf(b), sa = source.Skeleton.IndexOf("src_" + a), sb = source.Skeleton.IndexOf("src_" + b);
                for (int f = 0; f < source.FrameCount; f++)
                {
                    Vector3D dt = Vector3D.Read(tg, 3 * (f * jt + tb)) - Vector3D.Read(tg, 3 * (f * jt + ta));
                    Vector3D ds = Vector3D.Read(sg, 3 * (f * js + sb)) - Vector3D.Read(sg, 3 * (f * js + sa));
                    Assert.That(RetargetFixtures.Angle(dt, ds), Is.LessThan(1e-4), $"{a}→{b}, frame {f}");
                }
            }

            // Back onto the source: mapped joints exactly, the joints the model made up keep the source's own rotations.
            MotionClip back = map.ToSource(onModel, source);
            for (int f = 0; f < source.FrameCount; f++)
            {
                for (int s = 0; s < js; s++)
                {
                    Assert.That(RetargetFixtures.Angle(QuaternionD.Read(source.LocalRotations, source.RotationIndex(f, s)),
                        QuaternionD.Read(back.LocalRotations, back.RotationIndex(f, s))), Is.LessThan(1e-5), $"{source.Skeleton.Names[s]}, frame {f}");
                }
            }
        }

        [Test]
        public void ABuiltInMapMakesUpMissingToesButNotMissingLegs()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            var names = new List<string>(model.Names);
            names[4] = "LeftToeTip";
            names[8] = "RightToeTip";
            var source = new Skeleton(names, model.Parents, model.Offsets);
            SkeletonMap map = SkeletonMap.Create(ReferencePose.ModelTPose(source), ReferencePose.ModelTPose(model), null, "walk.bvh");
            Assert.That(map.SynthesizedJoints, Is.EqualTo(new[] { "LeftToe", "RightToe" }));
            Assert.That(map.UnmappedSourceJoints, Is.EqualTo(new[] { "LeftToeTip", "RightToeTip" }));
        }

        [Test]
        public void TheRootAndJointsBelowAMissingJointAreNeverMadeUp()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            var hipsNull = JointMap.FromJson("{\"Hips\": null}", "map.json", JointMap.Lafan1);
            var e = Assert.Throws<JointMapException>(() => SkeletonMap.Create(ReferencePose.ModelTPose(model), ReferencePose.ModelTPose(model), hipsNull, "x.bvh"));
            Assert.That(e!.MissingJoints, Is.EqualTo(new[] { "Hips" }));
        }

        [Test]
        public void JsonNullMeansSynthesizeAndABlankKeyIsRefusedWithItsLine()
        {
            JointMap map = JointMap.FromJson("{\n \"LeftToe\": null,\n \"Hips\": \"pelvis\"\n}", "m.json");
            Assert.That(map.IsSynthesized("LeftToe"), Is.True);
            Assert.That(map.MayLack("LeftToe"), Is.True);
            Assert.That(map.IsSynthesized("Hips"), Is.False);
            var e = Assert.Throws<DataFormatException>(() => JointMap.FromJson("{\n \"  \": \"pelvis\"\n}", "m.json"));
            Assert.That(e!.Message, Does.StartWith("m.json:2: "));
        }

        [Test]
        public void PoserNamesAreDetectedAndTheirToesAndSpine2MadeUp()
        {
            var names = new[] { "hip", "abdomen", "chest", "neck", "head", "lCollar", "lShldr", "lForeArm", "lHand", "rCollar", "rShldr", "rForeArm", "rHand", "lThigh", "lShin", "lFoot", "rThigh", "rShin", "rFoot" };
            var parents = new[] { -1, 0, 1, 2, 3, 2, 5, 6, 7, 2, 9, 10, 11, 0, 13, 14, 0, 16, 17 };
            Skeleton model = RetargetFixtures.Lafan1();
            var skeleton = new Skeleton(names, parents, new double[3 * names.Length]);
            Assert.That(JointMap.Detect(skeleton, model), Is.SameAs(JointMap.Poser));
        }

        [Test]
        public void APoserFileFromCmuMoreKeepsItsFeetOnTheGround()
        {
            string cmu = RetargetFixtures.RequireCmu();
            string file = Path.Combine(cmu, "..", "cmu-more", "35_01.bvh");
            if (!File.Exists(file)) Assert.Ignore($"{file} not found (../shared/data/cmu-more beside the repository); skipping the Poser data test");
            BvhAnimation poser = BvhReader.Read(file);
            Skeleton model = RetargetFixtures.Lafan1();
            SkeletonMap map = SkeletonMap.Create(ReferencePose.Default(poser.Skeleton), ReferencePose.ModelTPose(model), null, file);
            Assert.That(map.Map, Is.SameAs(JointMap.Poser));
            Assert.That(map.SynthesizedJoints, Is.EqualTo(new[] { "LeftToe", "RightToe", "Spine2" }));
            MotionClip onModel = map.ToTarget(poser.Motion);
            double[] g = RetargetFixtures.GlobalPositions(onModel);
            int toe = model.IndexOf("LeftToe"), foot = model.IndexOf("LeftFoot");
            double lowestToe = double.MaxValue, lowestFoot = double.MaxValue;
            for (int f = 10; f < onModel.FrameCount; f++)
            {
                lowestToe = Math.Min(lowestToe, g[3 * (f * 22 + toe) + 1]);
                lowestFoot = Math.Min(lowestFoot, g[3 * (f * 22 + foot) + 1]);
            }

            // A walk: the made-up toe reaches the ground (within 5 % of the leg), below the ankle.
            TestContext.WriteLine($"lowest toe {lowestToe:0.00}, lowest ankle {lowestFoot:0.00}, model leg {map.TargetLegLength:0.00}");
            Assert.That(Math.Abs(lowestToe), Is.LessThan(0.05 * map.TargetLegLength));
            Assert.That(lowestToe, Is.LessThan(lowestFoot));
        }
    }
}
