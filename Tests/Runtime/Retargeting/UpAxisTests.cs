using System;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>
    /// Issue 30: a Y-up skeleton in a Z-up world and a Z-up rest skeleton reach the model as the same walk
    /// authored Y up does (<see cref="UpAxisDecision"/>, <see cref="SkeletonMap"/>); a wrong forced axis is
    /// refused by <see cref="UpAxisDetection.RequireStanding"/>; a four-legged rig is refused by
    /// <see cref="BoneDirections.RequireTPose"/> with <see cref="BoneDirections.UprightBones"/>. All files are
    /// made here.
    /// </summary>
    public sealed class UpAxisTests
    {
        private static readonly Skeleton Model = RetargetFixtures.Lafan1();

        private static MotionClip AuthoredWalk() => UpAxisFixtures.Walk(UpAxisFixtures.Standing(Model, QuaternionD.Identity), 180, 1.0 / 60.0);

        private static (MotionClip OnModel, SkeletonMap Map) ToModel(MotionClip motion, UpAxis up, bool frameReference)
        {
            JointMap map = UpAxisFixtures.Map(Model);
            ReferencePose reference = frameReference ? ReferencePose.FromFrame(motion, 0) : ReferencePose.Zero(motion.Skeleton);
            UpAxisDecision decided = UpAxisDecision.Decide(up, reference, frameReference, motion, map);
            SkeletonMap skeletonMap = SkeletonMap.Create(reference, ReferencePose.ModelTPose(Model), map, "walk.bvh", null, decided);
            MotionClip onModel = skeletonMap.ToTarget(motion);
            UpAxisDetection.RequireStanding(onModel, "walk.bvh", decided.Description);
            return (onModel, skeletonMap);
        }

        private static void AssertSameMotion(MotionClip expected, MotionClip actual)
        {
            Assert.That(actual.FrameCount, Is.EqualTo(expected.FrameCount));
            double worstAngle = 0, worstRoot = 0;
            for (int f = 0; f < expected.FrameCount; f++)
            {
                for (int j = 0; j < Model.JointCount; j++)
                {
                    worstAngle = Math.Max(worstAngle, RetargetFixtures.Angle(
                        QuaternionD.Read(expected.LocalRotations, expected.RotationIndex(f, j)), QuaternionD.Read(actual.LocalRotations, actual.RotationIndex(f, j))));
                }

                worstRoot = Math.Max(worstRoot, (Vector3D.Read(expected.LocalPositions, expected.PositionIndex(f, 0)) - Vector3D.Read(actual.LocalPositions, actual.PositionIndex(f, 0))).Length);
            }

            TestContext.WriteLine($"largest local-rotation difference {worstAngle:E2} rad, root {worstRoot:E2} model units");
            Assert.That(worstAngle, Is.LessThan(1e-4));
            Assert.That(worstRoot, Is.LessThan(1e-4));
        }

        [TestCase(UpAxis.Auto, false)]
        [TestCase(UpAxis.Z, false)]
        [TestCase(UpAxis.Auto, true)]
        [TestCase(UpAxis.Z, true)]
        public void AYUpSkeletonInAZUpWorldReachesTheModelAsTheWalkAuthoredYUp(UpAxis up, bool frameReference)
        {
            MotionClip authored = AuthoredWalk();
            (MotionClip expected, SkeletonMap plain) = ToModel(authored, UpAxis.Auto, frameReference);
            Assert.That(plain.Up!.IsIdentity, Is.True, plain.Up.Description);
            (MotionClip actual, SkeletonMap map) = ToModel(UpAxisFixtures.InZUpWorld(authored), up, frameReference);
            TestContext.WriteLine(map.Up!.Description);
            Assert.That(map.Up.MotionUp, Is.EqualTo(UpAxis.Z));
            Assert.That(map.Up.ReferenceUp, Is.EqualTo(frameReference ? UpAxis.Z : UpAxis.Y));
            AssertSameMotion(expected, actual);
        }

        [TestCase(UpAxis.Auto)]
        [TestCase(UpAxis.Z)]
        public void AZUpRestSkeletonReachesTheModelAsTheWalkAuthoredYUp(UpAxis up)
        {
            MotionClip authored = AuthoredWalk();
            (MotionClip expected, _) = ToModel(authored, UpAxis.Auto, false);
            (MotionClip actual, SkeletonMap map) = ToModel(UpAxisFixtures.OnZUpSkeleton(authored), up, false);
            TestContext.WriteLine(map.Up!.Description);
            Assert.That(map.Up.MotionUp, Is.EqualTo(UpAxis.Z));
            Assert.That(map.Up.ReferenceUp, Is.EqualTo(UpAxis.Z));
            AssertSameMotion(expected, actual);
        }

        [Test]
        public void ForcingYOnAZUpWorldIsRefusedInOneLineNamingTheOption()
        {
            MotionClip zWorld = UpAxisFixtures.InZUpWorld(AuthoredWalk());
            var e = Assert.Throws<MotionRequestException>(() => ToModel(zWorld, UpAxis.Y, false));
            TestContext.WriteLine(e!.Message);
            Assert.That(e.Message, Does.StartWith("walk.bvh: after retargeting the motion lies down"));
            Assert.That(e.Message, Does.Contain("--up z"));
            Assert.That(e.Message, Does.Not.Contain("\n"));
        }

        [Test]
        public void ForcingYOnAZUpRestSkeletonIsRefused()
        {
            MotionClip zRest = UpAxisFixtures.OnZUpSkeleton(AuthoredWalk());
            // The rest pose is still judged on its own (it lies along Z), so the map is built; the motion then lies down.
            var e = Assert.Throws<MotionRequestException>(() => ToModel(zRest, UpAxis.Y, true));
            Assert.That(e!.Message, Does.Contain("lies down"));
        }

        [Test]
        public void ForcingZOnAYUpFileIsRefused()
        {
            // Turned, the reference frame lies too: refused before the motion is read, in one line naming --up.
            var e = Assert.Throws<JointMapException>(() => ToModel(AuthoredWalk(), UpAxis.Z, true));
            TestContext.WriteLine(e!.Message);
            Assert.That(e.Message, Does.Contain("does not stand on Y"));
            Assert.That(e.Message, Does.Contain("--up"));
            Assert.That(e.Message, Does.Not.Contain("\n"));
            var lying = Assert.Throws<MotionRequestException>(() => ToModel(AuthoredWalk(), UpAxis.Z, false));
            Assert.That(lying!.Message, Does.Contain("lies down"));
        }

        [Test]
        public void AFourLeggedRigWithAHumanoidMapIsRefusedNamingItsBones()
        {
            Skeleton quadruped = UpAxisFixtures.Quadruped(Model);
            SkeletonMap map = SkeletonMap.Create(ReferencePose.Zero(quadruped), ReferencePose.ModelTPose(Model), UpAxisFixtures.Map(Model), "dog.bvh");
            var e = Assert.Throws<JointMapException>(() => BoneDirections.RequireTPose(map, ReferencePose.ModelTPose(Model), BoneDirections.DefaultMaxDegrees, "dog.bvh", BoneDirections.UprightBones));
            TestContext.WriteLine(e!.Message);
            Assert.That(e.Message, Does.StartWith("dog.bvh: "));
            Assert.That(e.Message, Does.Contain("src_Spine (Spine)"));
            Assert.That(e.Message, Does.Contain("src_Neck (Neck)"));
            Assert.That(e.Message, Does.Contain("--reference-frame"));
            Assert.That(e.Message, Does.Contain("--map"));
        }

        [Test]
        public void AnArmsDownRestPoseAndAStandingFrameAreAccepted()
        {
            Skeleton armsDown = UpAxisFixtures.ArmsDown(Model);
            SkeletonMap rest = SkeletonMap.Create(ReferencePose.Zero(armsDown), ReferencePose.ModelTPose(Model), UpAxisFixtures.Map(Model), "rest.bvh");
            Assert.DoesNotThrow(() => BoneDirections.RequireTPose(rest, ReferencePose.ModelTPose(Model), BoneDirections.DefaultMaxDegrees, "rest.bvh", BoneDirections.UprightBones));
            // With arms compared (a reference declared a T-pose, the component's avatar) the same pose is refused: the arms are what differs.
            Assert.Throws<JointMapException>(() => BoneDirections.RequireTPose(rest, ReferencePose.ModelTPose(Model), BoneDirections.DefaultMaxDegrees, "rest.bvh"));
            MotionClip walk = AuthoredWalk();
            SkeletonMap frame = SkeletonMap.Create(ReferencePose.FromFrame(walk, 0), ReferencePose.ModelTPose(Model), UpAxisFixtures.Map(Model), "walk.bvh");
            Assert.DoesNotThrow(() => BoneDirections.RequireTPose(frame, ReferencePose.ModelTPose(Model), BoneDirections.DefaultMaxDegrees, "walk.bvh", BoneDirections.UprightBones));
        }

        [Test]
        public void UpAxisNamesParseAndRefuseOthers()
        {
            Assert.That(UpAxes.Parse("auto"), Is.EqualTo(UpAxis.Auto));
            Assert.That(UpAxes.Parse("Y"), Is.EqualTo(UpAxis.Y));
            Assert.That(UpAxes.Parse("z"), Is.EqualTo(UpAxis.Z));
            foreach (string bad in new[] { "", "x", "-z", "zz", "1", "y\n", "auto;rm" }) Assert.That(UpAxes.Parse(bad == "y\n" ? "y\nz" : bad), Is.Null, bad);
        }
    }
}
