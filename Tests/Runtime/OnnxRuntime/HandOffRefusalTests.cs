using System;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 27's new API refuses hostile input under the refusal contract (Documentation~/refusal-contract.md): an exception whose
    /// ParamName is the argument and whose message says what was expected, thrown before anything changes.
    /// </summary>
    [TestFixture]
    public sealed class HandOffRefusalTests
    {
        [TestCase(-1)]
        [TestCase(int.MinValue)]
        public void ANegativeLayerIsRefusedByTheStateTarget(int layer)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new StateTarget(layer, 1, 0));
            Assert.That(e!.ParamName, Is.EqualTo("layer"));
            Assert.That(e.Message, Does.Contain("expected"));
        }

        [TestCase(-0.01)]
        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void ATimeInTheStateThatIsNegativeOrNotFiniteIsRefused(double seconds)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new StateTarget(0, 1, seconds));
            Assert.That(e!.ParamName, Is.EqualTo("seconds"));
            Assert.That(e.Message, Does.Contain("expected"));
        }

        [Test]
        public void HandOffsTheControllerCannotServeAreRefusedAndChangeNothing()
        {
            using var loop = new StandInLoop(60, HandOffFrameLoopTests.Walking);
            loop.PlayUntil(0.5);
            int walk = loop.Controller.States[0].Hash;

            // A layer the controller does not have.
            var layer = Assert.Throws<ArgumentOutOfRangeException>(() => loop.RequestState(new StateTarget(1, walk, 0.5), 0.5));
            Assert.That(layer!.ParamName, Is.EqualTo("state"));
            Assert.That(layer.Message, Does.Contain("layer 1 is not a layer").And.Contain("; expected a layer index in 0..0"));

            // A state the controller does not have (the glue tells: Animator.HasState).
            var unknown = Assert.Throws<ArgumentException>(() => loop.RequestState(new StateTarget(0, 12345, 0.5), 0.5));
            Assert.That(unknown!.ParamName, Is.EqualTo("state"));
            Assert.That(unknown.Message, Does.Contain("no state of hash 12345").And.Contain("; expected"));

            // Seconds out of range: not positive, not finite, longer than the model spans.
            foreach (double seconds in new[] { 0.0, -1.0, double.NaN, double.PositiveInfinity, 9.0 })
            {
                var e = Assert.Throws<ArgumentOutOfRangeException>(() => loop.RequestState(new StateTarget(0, walk, 0.5), seconds), $"{seconds} s");
                Assert.That(e!.ParamName, Is.EqualTo("durationSeconds"), $"{seconds} s");
            }

            var none = Assert.Throws<ArgumentNullException>(() => loop.Character.Character.RequestState(new StateTarget(0, walk, 0.5), 0.5, null!));
            Assert.That(none!.ParamName, Is.EqualTo("controller"));

            // Nothing changed: no request, nothing waiting, nothing reported, the next frame plays the controller.
            Assert.That(loop.Player.IsPlaying, Is.False);
            Assert.That(loop.Player.HasDeferredTransition, Is.False);
            Assert.That(loop.Completions, Is.Empty);
            loop.Frame();
            Assert.That(loop.Last.SampleState, Is.False);
            Assert.That(loop.Last.Weight, Is.EqualTo(0));
        }

        [Test]
        public void LayerSettingsRefuseBadValues()
        {
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new LayerTransitionSettings(-1))!.ParamName, Is.EqualTo("layer"));
            var settings = new LayerTransitionSettings(0);
            foreach (double bad in new[] { -0.1, double.NaN, double.NegativeInfinity })
            {
                Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.MinSeconds = bad)!.ParamName, Is.EqualTo("MinSeconds"), $"{bad}");
                Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.MaxSeconds = bad)!.ParamName, Is.EqualTo("MaxSeconds"), $"{bad}");
            }

            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.MinSeconds = double.PositiveInfinity)!.ParamName, Is.EqualTo("MinSeconds"));
            Assert.That(settings.MinSeconds, Is.EqualTo(0), "a refused value leaves the setting as it was");
            Assert.That(settings.MaxSeconds, Is.EqualTo(double.MaxValue));
        }

        [Test]
        public void WatchingNothingIsRefused()
        {
            using var loop = new StandInLoop(60, HandOffFrameLoopTests.Walking);
            Assert.That(Assert.Throws<ArgumentNullException>(() => loop.Transitions.Watch(null!))!.ParamName, Is.EqualTo("settings"));
            Assert.That(loop.Transitions.Layers, Is.Empty);
        }

        [Test]
        public void ABoneMaskOfTheWrongLengthIsRefused()
        {
            var stream = new ArrayPoseStream(new double[3], new double[8]);
            var e = Assert.Throws<ArgumentException>(() => PoseBlend.ApplyMasked(ref stream, 1, new double[3], new double[8], new bool[3], new double[3], new double[8]));
            Assert.That(e!.ParamName, Is.EqualTo("keptBones"));
            Assert.That(e.Message, Does.Contain("one entry per bone (2)"));
        }
    }
}
