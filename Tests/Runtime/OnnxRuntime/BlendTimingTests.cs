using System;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 28, "clips on it play as on an Animation Track": a blend's history and target are read where the track plays
    /// its clips — a looping clip at its wrapped time, a clip at speed 2 at twice the track's pace — and its poses equal
    /// a bake of the same two clips at those times (the editor baker's Core path, the shipped model) to 1e-5.
    /// </summary>
    [TestFixture]
    public sealed class BlendTimingTests
    {
        private const double Tolerance = 1e-5;
        private const double Fps = 30;

        private Inbetweener _model = null!;
        private CharacterRig _rig = null!;
        private MotionClip _walk = null!;
        private MotionClip _jumps = null!;

        [OneTimeSetUp]
        public void Load()
        {
            DemoBlendClips clips = DemoBlendClips.Load();
            (_rig, _walk, _jumps) = (clips.Rig, clips.Walk, clips.Jumps);
            _model = TwoRigBakeTests.ShippedModel();
        }

        [OneTimeTearDown]
        public void Unload() => _model?.Dispose();

        [Test]
        public void ALoopingClipsHistoryIsReadAtTheWrappedTime()
        {
            // One second of the walk looping for 2.6 s on the track; the jumps start at 2.3 s: a 0.3 s blend (8 missing frames)
            // whose history, track times 2.0–2.3 s, is the loop's third cycle: animation times 0.0–0.3 s.
            IClipPoses loop = new MotionClipPoses("walk loop", _rig, _walk.Excerpt(0, 121));
            IClipPoses jumps = new MotionClipPoses("jumps", _rig, _jumps);
            var walkTiming = new TrackClipTiming(0, 2.6, 0, 1.0, loops: true);
            TrackLayout layout = TrackLayout.Create(new[] { walkTiming, new TrackClipTiming(2.3, 2.0, 0.2, 401 / 120.0) });
            TrackSpan span = layout.Spans[0];
            Assert.That(span.FromTime, Is.EqualTo(0.3).Within(1e-9), "the blend starts 0.3 s into the loop's third cycle");
            Assert.That(walkTiming.LocalTime(2.0 - 0.5 / Fps), Is.EqualTo(1.0 - 0.5 / Fps).Within(1e-9), "before the wrap: the end of the second cycle");

            BlendFrames frames = new BlendCache().Get(Model(), _rig, span, loop, jumps);
            Assert.That(frames.Mode, Is.EqualTo(BlendMode.Model));
            double worst = WorstDifference(frames, span, loop, jumps, t => (t % 1.0), 0.2 + 0.3);
            TestContext.WriteLine($"looping history: largest difference from the bake at wrapped times {worst:E2}");
            Assert.That(worst, Is.LessThan(Tolerance));

            // What it replaces, the history held at the animation's last frame, is another blend: the comparison resolves it.
            double held = WorstDifference(frames, span, loop, jumps, t => 1.0, 0.2 + 0.3);
            TestContext.WriteLine($"against a history held at the last frame: {held:E2}");
            Assert.That(held, Is.GreaterThan(1e-2));
        }

        [Test]
        public void ALoopingClipsTargetIsReadAtTheWrappedTime()
        {
            // The jumps loop and start 3.2 s into their 3.34 s animation: the blend's end, 0.3 s later, is 0.158 s into their second cycle.
            IClipPoses walk = new MotionClipPoses("walk", _rig, _walk);
            IClipPoses jumps = new MotionClipPoses("jumps", _rig, _jumps);
            double length = 400 / 120.0;
            TrackLayout layout = TrackLayout.Create(new[] { new TrackClipTiming(0, 2.6, 0, 3.0), new TrackClipTiming(2.3, 2.0, 3.2, length, loops: true) });
            TrackSpan span = layout.Spans[0];
            Assert.That(span.ToTime, Is.EqualTo(3.5 - length).Within(1e-9));

            BlendFrames frames = new BlendCache().Get(Model(), _rig, span, walk, jumps);
            Assert.That(frames.Mode, Is.EqualTo(BlendMode.Model));
            double worst = WorstDifference(frames, span, walk, jumps, t => t, 3.5 - length);
            TestContext.WriteLine($"looping target: largest difference from the bake at the wrapped time {worst:E2}");
            Assert.That(worst, Is.LessThan(Tolerance));
            double held = WorstDifference(frames, span, walk, jumps, t => t, length);
            TestContext.WriteLine($"against a target held at the last frame: {held:E2}");
            Assert.That(held, Is.GreaterThan(1e-2));
        }

        [Test]
        public void AClipAtSpeedTwoBlendsNeurallyAtTheTimesTheTrackPlaysIt()
        {
            // The walk at speed 2 (3 s of animation in 1.5 s), the jumps at speed 2 from 1.0 s: a 0.5 s blend, 14 missing
            // frames, history one model frame of track time apart (2/30 s of animation), target 0.2 + 2 × 0.5 s into the jumps.
            IClipPoses walk = new MotionClipPoses("walk", _rig, _walk);
            IClipPoses jumps = new MotionClipPoses("jumps", _rig, _jumps);
            TrackLayout layout = TrackLayout.Create(new[] { new TrackClipTiming(0, 1.5, 0, 3.0, speed: 2), new TrackClipTiming(1.0, 1.0, 0.2, 401 / 120.0, speed: 2) });
            TrackSpan span = layout.Spans[0];
            Assert.That((span.FromTime, span.ToTime), Is.EqualTo((2.0, 1.2)).Within(1e-9));

            BlendFrames frames = new BlendCache().Get(Model(), _rig, span, walk, jumps);
            Assert.That(frames.Mode, Is.EqualTo(BlendMode.Model), "no crossfade for a clip played faster");
            Assert.That(frames.FrameCount, Is.EqualTo(14 + 2));
            double worst = WorstDifference(frames, span, walk, jumps, t => 2 * t, 1.2);
            TestContext.WriteLine($"speed 2: largest difference from the bake at the track's times {worst:E2}");
            Assert.That(worst, Is.LessThan(Tolerance));

            // History taken one model frame of animation apart (as if the clip played at speed 1) is another blend.
            double unscaled = WorstDifference(frames, span, walk, jumps, t => 2.0 - (1.0 - t), 1.2);
            TestContext.WriteLine($"against history at speed 1: {unscaled:E2}");
            Assert.That(unscaled, Is.GreaterThan(1e-2));
        }

        [TestCase(0.0)]
        [TestCase(-2.0)]
        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        public void RefusesASpeedThatIsNoClipSpeed(double speed)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => _ = new TrackClipTiming(0, 1, 0, 1, speed));
            Assert.That(e!.ParamName, Is.EqualTo("speed"));
            Assert.That(e.Message, Does.Contain("expected"));
        }

        private BlendModel Model() => new BlendModel(_model.Contract, _model, maxBoneDeviationDegrees: 30);

        /// <summary>
        /// The largest difference between <paramref name="frames"/> and a bake laid out by hand: the first clip sampled at
        /// <paramref name="fromAnimationTime"/>(track time) for the model's past frames up to the span's start, the second at
        /// <paramref name="toTime"/>; compared at every model frame of the span and between them.
        /// </summary>
        private double WorstDifference(BlendFrames frames, TrackSpan span, IClipPoses from, IClipPoses to, Func<double, double> fromAnimationTime, double toTime)
        {
            int p = Model().PastFrames;
            int n = Model().MissingFrames(span.Duration);
            int bones = _rig.Skeleton.JointCount;
            CharacterPoseTrack track = DemoBlendClips.LaidOut(_rig, p, n, 1 / Fps, from, k => fromAnimationTime(span.Start - (p - 1 - k) / Fps), to, toTime);
            var root = new double[3];
            var rotations = new double[4 * bones];
            MotionClip bake = CharacterBake.Run(_model.Contract, track, null, new[] { BakeMethod.Model(_model) }, null, 30).Methods[0].OnRig;

            var expectedRoot = new double[3];
            var expectedRotations = new double[4 * bones];
            var frame = MotionClip.CreateRestPose(bake.Skeleton, 1, bake.FrameTime);
            double worst = 0;
            for (int i = 0; i <= 4 * (n + 1); i++)
            {
                double fraction = i / (4.0 * (n + 1));
                Assert.That(frames.Sample(fraction, root, rotations), Is.True);
                MotionResampler.Sample(bake, p - 1 + fraction * (n + 1), frame.LocalPositions, frame.LocalRotations);
                CharacterPoseTrack.ReadUnityPose(_rig, frame, 0, expectedRoot, expectedRotations);
                for (int v = 0; v < 3; v++) worst = Math.Max(worst, Math.Abs(root[v] - expectedRoot[v]));
                for (int v = 0; v < rotations.Length; v++) worst = Math.Max(worst, Math.Abs(rotations[v] - expectedRotations[v]));
            }

            return worst;
        }
    }
}
