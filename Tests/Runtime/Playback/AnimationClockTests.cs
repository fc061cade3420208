using DeltaInterpolator.Core.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// Which delta time a transition advances by, for each of the Animator's update modes (the component
    /// passes Unity's Time.deltaTime, unscaledDeltaTime and fixedDeltaTime; the choice is Core's).
    /// </summary>
    [TestFixture]
    public sealed class AnimationClockTests
    {
        private const double Scaled = 0.02;
        private const double Unscaled = 0.016;
        private const double Fixed = 0.01;

        [TestCase(AnimationClockMode.Scaled, FrameCallback.Update, true, Scaled)]
        [TestCase(AnimationClockMode.Scaled, FrameCallback.FixedUpdate, false, 0.0)]
        [TestCase(AnimationClockMode.Unscaled, FrameCallback.Update, true, Unscaled)]
        [TestCase(AnimationClockMode.Unscaled, FrameCallback.FixedUpdate, false, 0.0)]
        [TestCase(AnimationClockMode.Fixed, FrameCallback.Update, false, 0.0)]
        [TestCase(AnimationClockMode.Fixed, FrameCallback.FixedUpdate, true, Fixed)]
        public void EachModeAdvancesInItsCallbackByItsStep(AnimationClockMode mode, FrameCallback callback, bool drives, double step)
        {
            var clock = new AnimationClock { Mode = mode };
            Assert.That(clock.Advance(callback, Scaled, Unscaled, Fixed), Is.EqualTo(drives));
            Assert.That(clock.Time, Is.EqualTo(step));
        }

        [Test]
        public void TimeScaleZeroFreezesScaledTimeButNotUnscaledTime()
        {
            // Time.timeScale = 0: deltaTime is 0, unscaledDeltaTime is the real frame time, and no FixedUpdate runs.
            var normal = new AnimationClock { Mode = AnimationClockMode.Scaled };
            var unscaled = new AnimationClock { Mode = AnimationClockMode.Unscaled };
            for (int frame = 0; frame < 60; frame++)
            {
                normal.Advance(FrameCallback.Update, 0, 1.0 / 60, Fixed);
                unscaled.Advance(FrameCallback.Update, 0, 1.0 / 60, Fixed);
            }

            Assert.That(normal.Time, Is.EqualTo(0.0));
            Assert.That(unscaled.Time, Is.EqualTo(1.0).Within(1e-12));
        }

        [Test]
        public void FixedModeSumsThePhysicsStepsOfAFrameWhateverTheRenderedFrameTime()
        {
            var clock = new AnimationClock { Mode = AnimationClockMode.Fixed };
            // A slow frame: three physics steps, then the rendered frame (which does not advance it).
            for (int i = 0; i < 3; i++) clock.Advance(FrameCallback.FixedUpdate, 0.02, 0.05, 0.02);
            clock.Advance(FrameCallback.Update, 0.05, 0.05, 0.02);
            Assert.That(clock.Time, Is.EqualTo(0.06).Within(1e-12));
        }

        [Test]
        public void AModeChangeTakesEffectAtTheNextCallbackAndTimeStaysContinuous()
        {
            var clock = new AnimationClock { Mode = AnimationClockMode.Scaled };
            clock.Advance(FrameCallback.Update, 0.1, 0.2, 0.02);
            clock.Mode = AnimationClockMode.Unscaled;
            clock.Advance(FrameCallback.Update, 0.1, 0.2, 0.02);
            Assert.That(clock.Time, Is.EqualTo(0.3).Within(1e-12));
            Assert.That(clock.LastStep, Is.EqualTo(0.2));
        }

        [TestCase(-0.01)]
        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        public void NonsenseStepsCountAsZero(double delta)
        {
            Assert.That(AnimationClock.Step(AnimationClockMode.Scaled, delta, 0.1, 0.1), Is.EqualTo(0.0));
        }
    }
}
