using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Requests whose target pose the animation system samples later (the Unity component plays the target
    /// clip through its playable graph and reads it in the next evaluation, instead of writing it onto the
    /// scene): <see cref="TransitionPlayer.DeferTransition"/> then <see cref="TransitionPlayer.CompleteDeferredTransition"/>.
    /// A deferred request must arrive when the same request made at once would, report its id once, and give
    /// way to newer requests and <see cref="TransitionPlayer.Cancel"/> like any other.
    /// </summary>
    [TestFixture]
    public sealed class DeferredTransitionTests
    {
        private const double Fps = 60.0;

        [TestCase(1)]
        [TestCase(2)]
        public void ADeferredRequestArrivesWhenAndWhereTheSameRequestMadeAtOnceWould(int framesLate)
        {
            using var atOnce = new Character();
            using var deferred = new Character();
            atOnce.PlayUntil(1.0);
            deferred.PlayUntil(1.0);
            var (root, rotations) = atOnce.ClipPose(2.5);
            int a = atOnce.Player.RequestTransition(root, rotations, 0.5);
            int d = deferred.Player.DeferTransition(0.5);
            Assert.That(d, Is.EqualTo(a), "ids are handed out in request order either way");
            Assert.That(deferred.Player.HasDeferredTransition, Is.True);

            // The animation system evaluates the target clip while the character plays on (its own animation).
            for (int i = 0; i < framesLate; i++)
            {
                atOnce.Step();
                deferred.Step();
                Assert.That(deferred.Player.Weight, Is.EqualTo(0.0), "nothing to show before the target pose is known");
            }

            Assert.That(deferred.Player.CompleteDeferredTransition(root, rotations), Is.EqualTo(d));
            Assert.That(deferred.Player.HasDeferredTransition, Is.False);
            Assert.That(deferred.Player.TargetTime, Is.EqualTo(atOnce.Player.TargetTime).Within(1e-9), "the arrival time asked for when the request was made");

            while (atOnce.Completions.Count == 0)
            {
                atOnce.Step();
                deferred.Step();
            }

            Assert.That(deferred.Completions.Count, Is.EqualTo(1), "both arrive on the same rendered frame");
            Assert.That(deferred.Completions[0].RequestId, Is.EqualTo(d));
            Assert.That(deferred.Completions[0].ReachedTarget, Is.True);
            Assert.That(deferred.Player.PoseRotations.ToArray(), Is.EqualTo(atOnce.Player.PoseRotations.ToArray()).Within(1e-12), "both show the target");
        }

        [Test]
        public void WhileATargetIsSampledTheCurrentTransitionPlaysOnThenGivesWay()
        {
            using var c = new Character();
            c.PlayUntil(1.0);
            var (root, rotations) = c.ClipPose(2.0);
            int first = c.Player.RequestTransition(root, rotations, 0.8);
            c.PlayUntil(1.3);
            int second = c.Player.DeferTransition(0.5);
            c.Step();
            Assert.That(c.Player.IsPlaying, Is.True);
            Assert.That(c.Player.CurrentRequestId, Is.EqualTo(first), "the first transition plays on while the second's target is sampled");
            Assert.That(c.Completions, Is.Empty);

            c.Player.CompleteDeferredTransition(root, rotations);
            Assert.That(c.Player.CurrentRequestId, Is.EqualTo(second));
            Assert.That(c.Completions.Count, Is.EqualTo(1));
            Assert.That(c.Completions[0].RequestId, Is.EqualTo(first));
            Assert.That(c.Completions[0].ReachedTarget, Is.False);
        }

        [Test]
        public void ANewerRequestOrCancelEndsAWaitingOneAndReportsItOnce()
        {
            using var c = new Character();
            c.PlayUntil(1.0);
            var (root, rotations) = c.ClipPose(2.0);
            int first = c.Player.DeferTransition(0.5);
            int second = c.Player.DeferTransition(0.5);
            AssertEnded(c, first);
            c.Completions.Clear();

            int third = c.Player.RequestTransition(root, rotations, 0.5);
            AssertEnded(c, second);
            Assert.That(c.Player.HasDeferredTransition, Is.False);
            Assert.That(c.Player.CurrentRequestId, Is.EqualTo(third));
            c.Completions.Clear();

            int fourth = c.Player.DeferTransition(0.5);
            c.Player.Cancel();
            Assert.That(c.Completions.ConvertAll(e => e.RequestId), Is.EqualTo(new[] { third, fourth }), "the playing transition and the waiting one, in request order");
            Assert.That(c.Completions.TrueForAll(e => !e.ReachedTarget), Is.True);
            Assert.That(c.Player.HasDeferredTransition, Is.False);
            Assert.Throws<InvalidOperationException>(() => c.Player.CompleteDeferredTransition(root, rotations));
        }

        [Test]
        public void APoseThatComesAfterTheArrivalTimeArrivesOneModelFrameAfterIt()
        {
            using var c = new Character();
            c.PlayUntil(1.0);
            var (root, rotations) = c.ClipPose(2.0);
            c.Player.DeferTransition(0.1);
            // The Animator was culled for a while: the sample came 0.3 s later.
            c.PlayUntil(1.3);
            c.Player.CompleteDeferredTransition(root, rotations);
            Assert.That(c.Player.TargetTime, Is.EqualTo(c.Player.History.NewestTime + 1.0 / c.Player.FrameRate).Within(1e-9));
        }

        [Test]
        public void ADeferredRequestIsCheckedWhenItIsMade()
        {
            using var c = new Character();
            Assert.Throws<InvalidOperationException>(() => c.Player.DeferTransition(0.5), "no frame shown yet");
            c.PlayUntil(0.5);
            Assert.Throws<ArgumentOutOfRangeException>(() => c.Player.DeferTransition(0));
            Assert.Throws<ArgumentOutOfRangeException>(() => c.Player.DeferTransition(double.PositiveInfinity));
            Assert.Throws<ArgumentOutOfRangeException>(() => c.Player.DeferTransition(3600), "longer than the model spans");
            Assert.That(c.Player.HasDeferredTransition, Is.False);
            Assert.That(c.Completions, Is.Empty);
        }

        private static void AssertEnded(Character c, int id)
        {
            Assert.That(c.Completions.Count, Is.EqualTo(1));
            Assert.That(c.Completions[0].RequestId, Is.EqualTo(id));
            Assert.That(c.Completions[0].ReachedTarget, Is.False);
        }

        /// <summary>A character playing a synthetic clip at 60 fps with a player on the tiny model (SLERP only: deterministic and fast).</summary>
        private sealed class Character : IDisposable
        {
            private readonly SyntheticClip _clip;
            private readonly TransitionScheduler _decoder;
            private ArrayPoseStream _stream;

            public Character()
            {
                Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);
                _decoder = new MainThreadScheduler(model);
                ModelContract c = model.Contract;
                var map = new NamePoseConverter(c.Skeleton, c.UnitScale, c.Skeleton.Names);
                _clip = new SyntheticClip(c.JointCount, 5);
                Player = new TransitionPlayer(map, _decoder, new PlaybackSettings { BlendInSeconds = 0.1, BlendOutSeconds = 0.2, SlerpOnly = true });
                Player.TransitionCompleted += e => Completions.Add(e);
                _stream = new ArrayPoseStream(new double[3], new double[4 * c.JointCount]);
            }

            public TransitionPlayer Player { get; }

            public List<TransitionCompletion> Completions { get; } = new List<TransitionCompletion>();

            public double Time { get; private set; } = -1.0 / Fps;

            public (double[] Root, double[] Rotations) ClipPose(double time) => _clip.Pose(time);

            public void Step()
            {
                Time += 1.0 / Fps;
                _clip.Sample(Time, _stream.Root, _stream.Rotations);
                _decoder.Pump();
                Player.Step(Time, ref _stream);
            }

            public void PlayUntil(double time)
            {
                while (Time + 1.0 / Fps <= time + 1e-9) Step();
            }

            public void Dispose() => _decoder.Dispose();
        }
    }
}
