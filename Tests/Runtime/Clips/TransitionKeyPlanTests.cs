using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    public class TransitionKeyPlanTests
    {
        [Test]
        public void PastKeysStepBackOneModelFrameFromTheTransitionPoint()
        {
            TransitionKeyPlan plan = TransitionKeyPlan.Create(2.0, 0.5, 10, 15, 30);

            Assert.That(plan.PastFrames, Is.EqualTo(10));
            Assert.That(plan.FromTimes[9], Is.EqualTo(2.0).Within(1e-12));
            Assert.That(plan.FromTimes[0], Is.EqualTo(2.0 - 9.0 / 30).Within(1e-12));
            for (int k = 1; k < 10; k++) Assert.That(plan.FromTimes[k] - plan.FromTimes[k - 1], Is.EqualTo(1.0 / 30).Within(1e-12));
            Assert.That(plan.ToTime, Is.EqualTo(0.5));
            Assert.That(plan.TargetFrame, Is.EqualTo(25));
            Assert.That(plan.FrameCount, Is.EqualTo(26));
        }

        [Test]
        public void NearTheFirstClipsStartFewerPastKeysAreUsed()
        {
            // 0.1 s into the clip at 30 fps: frames at 0, 1/30, 2/30 and 0.1 exist before the point.
            TransitionKeyPlan plan = TransitionKeyPlan.Create(0.1, 0, 10, 5, 30);

            Assert.That(plan.PastFrames, Is.EqualTo(4));
            Assert.That(plan.FromTimes[0], Is.EqualTo(0).Within(1e-12));
            Assert.That(plan.TargetFrame, Is.EqualTo(9));
        }

        [Test]
        public void AGapOfNoFramesIsRefused()
        {
            Assert.That(() => TransitionKeyPlan.Create(1, 0, 10, 0, 30), Throws.InstanceOf<System.ArgumentOutOfRangeException>());
        }
    }
}
