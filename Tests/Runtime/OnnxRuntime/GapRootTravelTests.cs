using System;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 28: a gap carries root motion as the track's clips have it (<see cref="SpanRootTravel"/>, <see cref="SpanRootPlan"/>),
    /// on the Demo's CMU walk and jumps (their hips' travel read as the clips' root motion) and the shipped model: a 0.6 s
    /// gap from the walk's end (3 s) to the jumps (clip-in 0.2 s), 17 missing frames at 30 fps.
    /// </summary>
    [TestFixture]
    public sealed class GapRootTravelTests : DemoRootTravelFixture
    {
        private static TrackSpan Gap() => TrackLayout.Create(new[] { new TrackClipTiming(0, 3.0, 0, 3.0), new TrackClipTiming(3.6, 3.0, 0.2, 401 / 120.0) }).Spans[0];

        [Test]
        public void WithSceneOffsetsTheGapTravelsAlongTheModelsOwnTrajectory()
        {
            TrackSpan gap = Gap();
            SpanRootTravel travel = SpanRootPlan.Bake(new BlendCache(), Model, Rig, gap, Walk, Jumps, RootTravelMode.SceneOffset, default, out BlendFrames frames);
            Assert.That((frames.Mode, travel.FrameCount, travel.Mode), Is.EqualTo((BlendMode.Model, 19, RootTravelMode.SceneOffset)));
            RootPlacement[] trajectory = SpanRootTravel.Trajectory(Rig, frames);
            for (int k = 0; k < trajectory.Length; k++) Assert.That(Distance(travel.Frame(k), trajectory[k]), Is.EqualTo(0), $"frame {k} is the model's own");

            // It starts where the walk's root motion leaves the character and ends where the walk's last step, kept up, brings it.
            RootPlacement leaving = Placement(Walk, 3.0), walkStep = Placement(Walk, 3.0 - 1 / 30.0).StepTo(leaving);
            RootPlacement kept = leaving;
            for (int k = 0; k < 18; k++) kept = kept.Then(walkStep);
            double first = Distance(travel.Frame(0), leaving), last = Distance(travel.Frame(18), kept);
            // The jumps' first frame, placed there, is what the character shows at the gap's end: 0.5° facing error at most.
            RootPlacement arrivedPose = travel.Frame(18);
            TestContext.WriteLine($"scene offsets: first frame {first:E2} from the walk's end, last {last:E2} from the kept-up walk; walk step {walkStep}, first gap step {Step(travel, 0)}, last {Step(travel, 17)}");
            Assert.That(first, Is.LessThan(1e-5));
            Assert.That(last, Is.LessThan(1e-5));
            Assert.That(Distance(arrivedPose, kept), Is.LessThan(1e-5));
            // The model was given the walk's history: its first step continues the walk's (measured, not forced).
            Assert.That(Math.Abs(Step(travel, 0).Z - walkStep.Z), Is.LessThan(0.35 * Math.Abs(walkStep.Z)), "the first gap step continues the walk's pace");
        }

        [Test]
        public void WithTransformOffsetsTheGapLandsOnTheSecondClipsPlacementWithTheClipsOwnSteps()
        {
            TrackSpan gap = Gap();
            // The jumps placed 1 unit to the side, 10 ahead (the walk covers 10.4 in 0.6 s) and turned 25° from where the walk leaves the character.
            var arrival = new RootPlacement(1.0, 10.0, 25 * Math.PI / 180);
            SpanRootTravel travel = SpanRootPlan.Bake(new BlendCache(), Model, Rig, gap, Walk, Jumps, RootTravelMode.TransformOffset, arrival, out BlendFrames frames);
            RootPlacement leaving = Placement(Walk, 3.0);
            RootPlacement walkStep = Placement(Walk, 3.0 - 1 / 30.0).StepTo(leaving);
            RootPlacement jumpsStep = Placement(Jumps, 0.2).StepTo(Placement(Jumps, 0.2 + 1 / 30.0));
            Assert.That(Distance(travel.Frame(0), leaving), Is.LessThan(1e-5), "the first frame: where the walk's root motion leaves the character");
            Assert.That(Distance(travel.Frame(18), leaving.Then(arrival)), Is.LessThan(1e-12), "the last frame: the jumps' placement");
            Assert.That(Distance(Step(travel, 0), walkStep), Is.LessThan(1e-9), "the first step is the walk's last");
            Assert.That(Distance(Step(travel, 17), jumpsStep), Is.LessThan(1e-9), "the last step is the jumps' first");
            double inside = AssertNoJump(travel, walkStep, jumpsStep, "transform offsets");
            double pace = Math.Sqrt(walkStep.X * walkStep.X + walkStep.Z * walkStep.Z);
            Assert.That(inside, Is.LessThan(0.25 * pace), "inside the gap the step changes smoothly: by under a quarter of the walk's step from one frame to the next (measured 0.08 of 0.58)");

            // The model went to the placed target itself: its trajectory ends there within the bake's precision, so the bend is small.
            RootPlacement[] trajectory = SpanRootTravel.Trajectory(Rig, frames);
            double bend = 0;
            for (int k = 0; k < trajectory.Length; k++) bend = Math.Max(bend, Distance(travel.Frame(k), trajectory[k]));
            TestContext.WriteLine($"transform offsets: largest bend from the model's trajectory {bend:F4}");
        }

        [Test]
        public void ATrajectoryThatEndsElsewhereIsBentToLandExactly()
        {
            // The gap baked without root motion: the model's hips go to the jumps' own start, far from where the walk stands.
            TrackSpan gap = Gap();
            SpanRootPlan.Bake(new BlendCache(), Model, Rig, gap, Walk, Jumps, RootTravelMode.None, default, out BlendFrames frames);
            RootPlacement[] trajectory = SpanRootTravel.Trajectory(Rig, frames);
            var target = trajectory[0].Then(new RootPlacement(-0.3, 2.2, -40 * Math.PI / 180));
            var lastStep = new RootPlacement(0.001, 0.045, 0.002);
            var firstStep = new RootPlacement(-0.002, 0.03, -0.01);
            SpanRootTravel travel = SpanRootTravel.Land(trajectory, target, lastStep, firstStep);
            TestContext.WriteLine($"unplaced model trajectory ends {Distance(trajectory[18], target):F3} from the target");
            Assert.That(Distance(trajectory[18], target), Is.GreaterThan(0.5), "the test's premise: the model's own end is elsewhere");
            Assert.That(Distance(travel.Frame(0), trajectory[0]), Is.EqualTo(0));
            Assert.That(Distance(travel.Frame(18), target), Is.LessThan(1e-12));
            Assert.That(Distance(Step(travel, 0), lastStep), Is.LessThan(1e-9));
            Assert.That(Distance(Step(travel, 17), firstStep), Is.LessThan(1e-9));
            AssertNoJump(travel, lastStep, firstStep, "bent");

            // Too short for both steps (3 model frames): it still lands, linearly.
            SpanRootTravel shortGap = SpanRootTravel.Land(trajectory.AsSpan(0, 3), target, lastStep, firstStep);
            Assert.That(Distance(shortGap.Frame(2), target), Is.LessThan(1e-12));
            Assert.That(Distance(shortGap.Frame(0), trajectory[0]), Is.EqualTo(0));
        }

        [Test]
        public void ClipsWithoutRootMotionKeepTheGapAsItWas()
        {
            TrackSpan gap = Gap();
            var cache = new BlendCache();
            BlendFrames plain = cache.Get(Model, Rig, gap, Walk, Jumps);
            SpanRootTravel travel = SpanRootPlan.Bake(cache, Model, Rig, gap, Walk, Jumps, RootTravelMode.None, default, out BlendFrames frames);
            Assert.That(frames, Is.SameAs(plain), "the same bake as without root travel");
            Assert.That(cache.Computed, Is.EqualTo(1));
            Assert.That(travel.Mode, Is.EqualTo(RootTravelMode.None));
            AssertTravelMovesNothing(travel, frames, 0.37, gap.Duration);
        }

        [Test]
        public void RootAndInPlacePoseTogetherShowTheModelsPoseAndTheVelocityAddsUpToTheTravel()
        {
            TrackSpan gap = Gap();
            var arrival = new RootPlacement(1.0, 10.0, 25 * Math.PI / 180);
            SpanRootTravel travel = SpanRootPlan.Bake(new BlendCache(), Model, Rig, gap, Walk, Jumps, RootTravelMode.TransformOffset, arrival, out BlendFrames frames);
            int bones = Rig.Skeleton.JointCount;
            double[] root = new double[3], rotations = new double[4 * bones], moved = new double[3], movedRotations = new double[4 * bones];
            foreach (double fraction in new[] { 0.0, 0.13, 0.5, 0.77, 1.0 })
            {
                frames.Sample(fraction, root, rotations);
                root.CopyTo(moved, 0);
                rotations.CopyTo(movedRotations, 0);
                travel.InPlace(Rig, fraction, moved, movedRotations.AsSpan(0, 4));
                travel.At(fraction).Move(Rig, moved, movedRotations.AsSpan(0, 4));
                double worst = 0;
                for (int i = 0; i < 3; i++) worst = Math.Max(worst, Math.Abs(moved[i] - root[i]));
                for (int i = 0; i < 4; i++) worst = Math.Max(worst, Math.Abs(Math.Abs(movedRotations[i]) - Math.Abs(rotations[i])));
                Assert.That(worst, Is.LessThan(1e-12), $"at {fraction}: the root placed there and the pose in place show the model's pose");
            }

            // The engine applies the velocity in the root's own frame, one model frame at a time: it arrives where the travel ends.
            double frameSeconds = gap.Duration / 18;
            RootPlacement applied = travel.Frame(0);
            for (int k = 0; k < 18; k++)
            {
                travel.Velocity((k + 0.0) / 18, gap.Duration, out double x, out double z, out double yawRate);
                applied = applied.Then(new RootPlacement(x * frameSeconds, z * frameSeconds, yawRate * frameSeconds));
            }

            Assert.That(Distance(applied, travel.Frame(18)), Is.LessThan(1e-9));
        }

        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void ReadingTheTravelAtThePlayheadAllocatesNothing()
        {
            TrackSpan gap = Gap();
            SpanRootTravel travel = SpanRootPlan.Bake(new BlendCache(), Model, Rig, gap, Walk, Jumps, RootTravelMode.SceneOffset, default, out BlendFrames frames);
            double[] root = new double[3], rotations = new double[4 * Rig.Skeleton.JointCount];
            double sum = 0;
            void Frame(int i)
            {
                double fraction = (i % 60) / 59.0;
                frames.Sample(fraction, root, rotations);
                travel.InPlace(Rig, fraction, root, rotations.AsSpan(0, 4));
                travel.Velocity(fraction, gap.Duration, out double x, out double z, out double yawRate);
                sum += x + z + yawRate + travel.At(fraction).Yaw;
            }

            // Warm-up past the runtime's tiered compilation (its first calls and loops are recompiled, which can count as this thread's bytes).
            for (int i = 0; i < 2000; i++) Frame(i);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 1000; i++) Frame(i);
            long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
            TestContext.WriteLine($"1000 playhead reads with root travel: {bytes} bytes allocated");
            Assert.That(bytes, Is.EqualTo(0));
            Assert.That(double.IsFinite(sum));
        }

        [Test]
        public void RefusesWhatIsNoSpanOrPlacement()
        {
            var e = Assert.Throws<ArgumentException>(() => SpanRootPlan.Bake(new BlendCache(), Model, Rig, default, Walk, Jumps, RootTravelMode.SceneOffset, default, out _));
            Assert.That(e!.ParamName, Is.EqualTo("span"));
            Assert.That(e.Message, Does.Contain("; expected a blend or gap"));
            var m = Assert.Throws<ArgumentOutOfRangeException>(() => SpanRootPlan.Bake(new BlendCache(), Model, Rig, Gap(), Walk, Jumps, (RootTravelMode)7, default, out _));
            Assert.That(m!.ParamName, Is.EqualTo("mode"));
            var p = Assert.Throws<ArgumentOutOfRangeException>(() => _ = new PlacedClipPoses(Jumps, Rig, new RootPlacement(double.NaN, 0, 0)));
            Assert.That(p!.ParamName, Is.EqualTo("placement"));
            var t = Assert.Throws<ArgumentException>(() => SpanRootTravel.Follow(new RootPlacement[1]));
            Assert.That(t!.ParamName, Is.EqualTo("trajectory"));
            Assert.Throws<ArgumentOutOfRangeException>(() => SpanRootTravel.None(1));
        }

        /// <summary>No jump in travel per frame at either end: the gap's first step is the first clip's last, its last the second clip's first. Returns the largest step change inside.</summary>
        private static double AssertNoJump(SpanRootTravel travel, RootPlacement before, RootPlacement after, string what)
        {
            int last = travel.FrameCount - 1;
            double worst = Math.Max(Distance(Step(travel, 0), before), Distance(Step(travel, last - 1), after));
            double inside = 0;
            for (int k = 1; k < last; k++) inside = Math.Max(inside, Distance(Step(travel, k), Step(travel, k - 1)));
            TestContext.WriteLine($"{what}: step change at the ends {worst:E2}, largest inside {inside:F4} per frame");
            Assert.That(worst, Is.LessThan(1e-9), $"{what}: no jump at either end");
            return inside;
        }
    }
}
