using DeltaInterpolator.Core.Baking;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Baking
{
    public sealed class KeyFramesTests
    {
        [Test]
        public void EveryCountsFromTheFirstUsableFrame()
        {
            Assert.That(KeyFrames.Every(60, 353, 10, 5), Is.EqualTo(new[] { 10, 70, 130, 190, 250, 310, 352 }));
        }

        [Test]
        public void ALastFrameTooCloseToTheKeyBeforeItMergesTheLastGap()
        {
            // 0, 60, …, 120 and the last frame 122: two frames after a key, less than one model frame at 120 fps.
            Assert.That(KeyFrames.Every(60, 123, 0, 5), Is.EqualTo(new[] { 0, 60, 122 }));
            Assert.That(KeyFrames.Every(60, 126, 0, 5), Is.EqualTo(new[] { 0, 60, 120, 125 }));
            Assert.That(KeyFrames.Every(60, 61, 0, 5), Is.EqualTo(new[] { 0, 60 }));
        }

        [Test]
        public void TooFewUsableFramesAreRefused()
        {
            Assert.Throws<KeyLayoutException>(() => KeyFrames.Every(60, 12, 11, 1));
            Assert.Throws<KeyLayoutException>(() => KeyFrames.Every(60, 14, 10, 5));
        }
    }
}
