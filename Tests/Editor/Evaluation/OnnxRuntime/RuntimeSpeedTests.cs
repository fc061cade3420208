using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Evaluation.Speed;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The measurements behind <c>inbetween speed</c> on the tiny fixture model: every timing has its samples
    /// and a p95 at or above its median, lazy decoding is timed when the lazy graphs are there, a transition
    /// allocates nothing in steady state, and the crowd benchmark reports the crowd it built.
    /// </summary>
    [TestFixture]
    public sealed class RuntimeSpeedTests
    {
        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void EveryMeasurementIsTakenAndATransitionAllocatesNothing()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            SpeedResults speed = RuntimeSpeed.Measure(model, () => OnnxRuntimeBackend.Load(Fixtures.TinyModel), 10);
            Assert.That(speed.Transition, Has.Count.EqualTo(RuntimeSpeed.Lengths.Count));
            Assert.That(speed.Network, Has.Count.EqualTo(RuntimeSpeed.Lengths.Count));
            foreach (Timing t in speed.Transition) AssertTiming(t);
            foreach (Timing t in speed.Network) AssertTiming(t);
            AssertTiming(speed.SlerpFk);
            Assert.That(model.SupportsLazyDecoding, Is.True, "the fixture ships its lazy graphs");
            AssertTiming(speed.LazyFrame!.Value);
            Assert.That(speed.LazyFrameFraction, Is.EqualTo(speed.LazyFrame.Value.Median / speed.TransitionAt(RuntimeSpeed.LazyLength).Median));
            Assert.That(speed.AllocatedBytesPerTransition, Is.EqualTo(0), "the inference hot path allocates nothing in steady state");
        }

        [Test]
        public void TheCrowdBenchmarkReportsItsCrowd()
        {
            CrowdTimings crowd = CrowdBenchmark.Run(() => OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true), 2);
            Assert.That(crowd.Characters, Is.EqualTo(2));
            Assert.That(crowd.AllFramesMs, Is.GreaterThanOrEqualTo(crowd.AllFirstFramesMs));
            Assert.That(crowd.FrameMsBatched, Is.GreaterThan(0));
            Assert.That(crowd.FrameMsUnbatched, Is.GreaterThan(0));
            // Inference is part of the rendered frame, which also holds every player's playback.
            Assert.That(crowd.StepMsBatched, Is.GreaterThanOrEqualTo(crowd.FrameMsBatched));
            Assert.That(crowd.StepMsUnbatched, Is.GreaterThanOrEqualTo(crowd.FrameMsUnbatched));
            Assert.That(crowd.FrozenFrames, Is.GreaterThanOrEqualTo(0));
        }

        private static void AssertTiming(Timing t)
        {
            Assert.That(t.Samples, Is.InRange(10, 40));
            Assert.That(t.Median, Is.GreaterThan(0));
            Assert.That(t.P95, Is.GreaterThanOrEqualTo(t.Median));
        }
    }
}
