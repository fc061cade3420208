using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    public sealed class SkeletonMapTests
    {
        private static readonly string[] Perturbed = { "LeftArm", "RightForeArm", "LeftUpLeg", "RightLeg", "LeftFoot", "Neck", "RightShoulder" };

        private static (SkeletonMap Map, MotionClip Source) Build(int seed, double unit, double yaw)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            (Skeleton skeleton, ReferencePose reference) = RetargetFixtures.Source(model, seed, unit, yaw, Perturbed);
            JointMap map = JointMap.FromJson(RetargetFixtures.SourceMapJson(model), "test-map.json");
            SkeletonMap m = SkeletonMap.Create(reference, ReferencePose.ModelTPose(model), map, "generated source");
            MotionClip motion = RetargetFixtures.Motion(reference, 48, 1.0 / 120.0, seed + 1, 0.05 * unit * 100.0, "src_LeftHipJoint");
            return (m, motion);
        }

        [TestCase(1, 0.0254, 0.0)]
        [TestCase(2, 0.37, 70.0)]
        [TestCase(3, 1.0, -135.0)]
        public void ToTargetAndBackReturnsTheMappedLocalRotations(int seed, double unit, double yaw)
        {
            (SkeletonMap map, MotionClip source) = Build(seed, unit, yaw);
            MotionClip onModel = map.ToTarget(source);
            MotionClip back = map.ToSource(onModel, source);

            Assert.That(back.FrameCount, Is.EqualTo(source.FrameCount));
            double worst = 0;
            for (int f = 0; f < source.FrameCount; f++)
            {
                for (int j = 0; j < map.Target.JointCount; j++)
                {
                    int s = map.SourceJointOf(j);
                    worst = Math.Max(worst, RetargetFixtures.Angle(
                        QuaternionD.Read(source.LocalRotations, source.RotationIndex(f, s)),
                        QuaternionD.Read(back.LocalRotations, back.RotationIndex(f, s))));
                }

                // The unmapped hip joint and finger keep the source's own rotations.
                foreach (string name in new[] { "src_LeftHipJoint", "src_LeftFinger" })
                {
                    int s = map.Source.IndexOf(name);
                    Assert.That(RetargetFixtures.Angle(
                        QuaternionD.Read(source.LocalRotations, source.RotationIndex(f, s)),
                        QuaternionD.Read(back.LocalRotations, back.RotationIndex(f, s))), Is.LessThan(1e-12));
                }

                Vector3D root = Vector3D.Read(source.LocalPositions, source.PositionIndex(f, 0));
                Vector3D rootBack = Vector3D.Read(back.LocalPositions, back.PositionIndex(f, 0));
                Assert.That((root - rootBack).Length, Is.LessThan(1e-9 * Math.Max(1.0, root.Length)));
            }

            TestContext.WriteLine($"seed {seed}, unit {unit}, yaw {yaw}°: largest local-rotation error after model and back {worst:E2} rad; root scale {map.RootScale:G6}");
            Assert.That(worst, Is.LessThan(1e-5));
        }

        [TestCase(1, 0.0254, 0.0)]
        [TestCase(2, 0.37, 70.0)]
        [TestCase(3, 1.0, -135.0)]
        public void MappedBonesPointTheSameWayOnEveryFrame(int seed, double unit, double yaw)
        {
            (SkeletonMap map, MotionClip source) = Build(seed, unit, yaw);
            MotionClip onModel = map.ToTarget(source);
            double[] ps = RetargetFixtures.GlobalPositions(source);
            double[] pt = RetargetFixtures.GlobalPositions(onModel);
            int js = map.Source.JointCount, jt = map.Target.JointCount;
            double worst = 0;
            int bones = 0;
            for (int f = 0; f < source.FrameCount; f++)
            {
                for (int c = 1; c < jt; c++)
                {
                    int p = map.Target.Parents[c];
                    Vector3D a = Vector3D.Read(pt, (f * jt + c) * 3) - Vector3D.Read(pt, (f * jt + p) * 3);
                    // The source bone: from the parent's source joint to the first joint of the child's chain.
                    int sc = map.Source.IndexOf("src_" + map.Target.Names[c]);
                    Vector3D b = Vector3D.Read(ps, (f * js + sc) * 3) - Vector3D.Read(ps, (f * js + map.SourceJointOf(p)) * 3);
                    if (a.Length < 1e-9 || b.Length < 1e-9) continue;
                    worst = Math.Max(worst, RetargetFixtures.Angle(a, b));
                    if (f == 0) bones++;
                }
            }

            TestContext.WriteLine($"seed {seed}: {bones} bones × {source.FrameCount} frames, largest world direction difference {worst:E2} rad");
            Assert.That(bones, Is.EqualTo(jt - 1));
            Assert.That(worst, Is.LessThan(1e-4));
        }

        [Test]
        public void TheTargetFacesWhereTheSourceFaces()
        {
            (SkeletonMap map, MotionClip source) = Build(4, 0.5, 90.0);
            MotionClip onModel = map.ToTarget(source);
            // The model's facing axis is the hips' local +Y; in the T-pose it points along +Z, so after a
            // source turned by 90° about Y it points along +X at the reference.
            Vector3D facing = Quaternions.Apply(map.TargetReference.GlobalRotation(0), Vector3D.UnitY);
            Assert.That((facing - Vector3D.UnitX).Length, Is.LessThan(1e-9));
            Assert.That(onModel.FrameCount, Is.EqualTo(source.FrameCount));
        }

        [Test]
        public void LafanMotionReachesTheModelUnchangedWithTheDefaultReference()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            // Another LaFAN1 actor: the same joints and axes, other bone lengths.
            var offsets = new double[model.Offsets.Count];
            for (int i = 0; i < offsets.Length; i++) offsets[i] = 1.1 * model.Offsets[i];
            Skeleton actor = model.WithOffsets(offsets);
            MotionClip clip = RetargetFixtures.Motion(ReferencePose.ModelTPose(actor), 30, 1.0 / 30.0, 41, 3.0);
            SkeletonMap map = SkeletonMap.Create(ReferencePose.Default(actor), ReferencePose.ModelTPose(model), null, "lafan.bvh");
            Assert.That(map.Map, Is.SameAs(JointMap.Lafan1));
            MotionClip onModel = map.ToTarget(clip);
            double worst = 0;
            for (int i = 0; i < clip.FrameCount * 22; i++)
            {
                worst = Math.Max(worst, RetargetFixtures.Angle(QuaternionD.Read(clip.LocalRotations, 4 * i), QuaternionD.Read(onModel.LocalRotations, 4 * i)));
            }

            Assert.That(worst, Is.LessThan(1e-9));
            Assert.That(map.RootScale, Is.EqualTo(1.0 / 1.1).Within(1e-9));
        }

        [Test]
        public void MissingJointsAreRefusedWithTheirNames()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            var names = new List<string>(model.Names);
            // Knees cannot be made up (toes, upper chest, neck and shoulders can: JointSynthesisTests).
            names[2] = "LeftKnee";
            names[6] = "RightKnee";
            var source = new Skeleton(names, model.Parents, model.Offsets);
            var e = Assert.Throws<JointMapException>(() => SkeletonMap.Create(ReferencePose.Zero(source), ReferencePose.ModelTPose(model), null, "walk.bvh"));
            Assert.That(e!.MissingJoints, Is.EqualTo(new[] { "LeftLeg", "RightLeg" }));
            Assert.That(e.Message, Does.StartWith("walk.bvh: "));
            Assert.That(e.Message, Does.Contain("LeftLeg").And.Contain("RightLeg").And.Contain("2 of the target's 22 joints"));
            Assert.That(e.Message, Does.Not.Contain("\n"));
        }

        [Test]
        public void AChainThatBreaksTheHierarchyIsRefused()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            // LeftLeg mapped to a joint that is not below LeftUpLeg's source joint.
            JointMap map = JointMap.FromJson("{\"LeftLeg\": \"RightLeg\", \"RightLeg\": \"LeftLeg\"}", "swap.json", JointMap.Lafan1);
            var e = Assert.Throws<JointMapException>(() => SkeletonMap.Create(ReferencePose.Zero(model), ReferencePose.ModelTPose(model), map, "x.bvh"));
            Assert.That(e!.Message, Does.Contain("not below"));
        }

        [Test]
        public void UnmappedJointsAreSlerpedBetweenKeysWhenKeysAreGiven()
        {
            (SkeletonMap map, MotionClip source) = Build(5, 0.3, 20.0);
            MotionClip onModel = map.ToTarget(source);
            int[] keys = { 0, 12, 40 };
            MotionClip back = map.ToSource(onModel, source, keys);
            int finger = map.Source.IndexOf("src_LeftFinger");
            QuaternionD k12 = QuaternionD.Read(source.LocalRotations, source.RotationIndex(12, finger));
            QuaternionD k40 = QuaternionD.Read(source.LocalRotations, source.RotationIndex(40, finger));
            for (int f = 12; f <= 40; f++)
            {
                QuaternionD expected = Quaternions.Normalize(Quaternions.Slerp(k12, k40, (f - 12) / 28.0));
                Assert.That(RetargetFixtures.Angle(expected, QuaternionD.Read(back.LocalRotations, back.RotationIndex(f, finger))), Is.LessThan(1e-9), $"frame {f}");
            }

            // After the last key the last key's rotation is held; mapped joints still follow the target.
            QuaternionD held = QuaternionD.Read(back.LocalRotations, back.RotationIndex(45, finger));
            Assert.That(RetargetFixtures.Angle(held, k40), Is.LessThan(1e-12));
            int s = map.SourceJointOf(map.Target.IndexOf("LeftForeArm"));
            Assert.That(RetargetFixtures.Angle(
                QuaternionD.Read(back.LocalRotations, back.RotationIndex(30, s)),
                QuaternionD.Read(source.LocalRotations, source.RotationIndex(30, s))), Is.LessThan(1e-5));
        }

        [Test]
        public void ToSourceAtAnotherRateSamplesTheSourceAtTheTargetsTimes()
        {
            (SkeletonMap map, MotionClip source) = Build(6, 0.3, 0.0);
            MotionClip at30 = MotionResampler.Resample(map.ToTarget(source), 1.0 / 30.0);
            MotionClip back = map.ToSource(at30, source);
            Assert.That(back.FrameTime, Is.EqualTo(1.0 / 30.0));
            Assert.That(back.FrameCount, Is.EqualTo(12));
            // 120 → 30 fps keeps every fourth frame, so frame i of the result is source frame 4i.
            for (int f = 0; f < back.FrameCount; f++)
            {
                for (int k = 0; k < map.Source.JointCount; k++)
                {
                    Assert.That(RetargetFixtures.Angle(
                        QuaternionD.Read(source.LocalRotations, source.RotationIndex(4 * f, k)),
                        QuaternionD.Read(back.LocalRotations, back.RotationIndex(f, k))), Is.LessThan(1e-5), $"frame {f}, joint {map.Source.Names[k]}");
                }
            }
        }
    }
}
