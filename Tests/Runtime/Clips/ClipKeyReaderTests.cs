using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    public class ClipKeyReaderTests
    {
        [Test]
        public void KeysOfAllCurvesBecomeOneSortedSetOfFrames()
        {
            var curves = new List<IReadOnlyList<float>>
            {
                new[] { 0f, 0.5f, 1f },        // a rotation curve keyed at 0, 15, 30
                new[] { 0f, 1f / 3f, 1f },     // another bone keyed at 0, 10, 30
                new[] { 0.5f },                // a position curve sharing frame 15
            };

            ClipKeyFrames keys = ClipKeyReader.Read(curves, 30, 1.0);

            Assert.That(keys.Frames, Is.EqualTo(new[] { 0, 10, 15, 30 }));
            Assert.That(keys.SnappedKeys, Is.EqualTo(0));
            Assert.That(keys.IgnoredKeys, Is.EqualTo(0));
            Assert.That(keys.GapCount, Is.EqualTo(3));
            Assert.That(new[] { keys.GapLength(0), keys.GapLength(1), keys.GapLength(2) }, Is.EqualTo(new[] { 9, 4, 14 }));
            Assert.That(keys.FrameCount, Is.EqualTo(31));
        }

        [Test]
        public void GapsOutsideTheTrainedRangeAreListed()
        {
            // Gaps of 9, 4 and 14 frames against a model trained on 5–39: only the 4 is outside.
            var curves = new List<IReadOnlyList<float>> { new[] { 0f, 1f / 3f, 0.5f, 1f } };
            ClipKeyFrames keys = ClipKeyReader.Read(curves, 30, 1.0);

            Assert.That(keys.GapsOutside(5, 39), Is.EqualTo(new[] { 4 }));
            Assert.That(keys.GapsOutside(1, 10), Is.EqualTo(new[] { 14 }));
            Assert.That(keys.GapsOutside(0, 0), Is.Empty, "unknown range");
        }

        [Test]
        public void KeysBetweenFramesAreRoundedAndCounted()
        {
            // 60 fps keys on a 30 fps model: 1/60 s is half a frame (rounds up), 0.1 s is frame 3 exactly.
            var curves = new List<IReadOnlyList<float>> { new[] { 0f, 1f / 60f, 0.1f, 0.21f } };

            ClipKeyFrames keys = ClipKeyReader.Read(curves, 30, 0.3);

            Assert.That(keys.Frames, Is.EqualTo(new[] { 0, 1, 3, 6 }));
            Assert.That(keys.SnappedKeys, Is.EqualTo(2));
            Assert.That(keys.LargestSnapFrames, Is.EqualTo(0.5).Within(1e-5));
        }

        [Test]
        public void KeysOutsideTheClipAreLeftOut()
        {
            var curves = new List<IReadOnlyList<float>> { new[] { -0.5f, 0f, 0.5f, 2f } };

            ClipKeyFrames keys = ClipKeyReader.Read(curves, 30, 1.0);

            Assert.That(keys.Frames, Is.EqualTo(new[] { 0, 15 }));
            Assert.That(keys.IgnoredKeys, Is.EqualTo(2));
        }

        [Test]
        public void AdjacentKeysLeaveNoGap()
        {
            ClipKeyFrames keys = ClipKeyReader.Read(new List<IReadOnlyList<float>> { new[] { 0f, 1f / 30f, 2f / 30f } }, 30, 0.1);

            Assert.That(keys.Frames, Is.EqualTo(new[] { 0, 1, 2 }));
            Assert.That(keys.GapCount, Is.EqualTo(0));
        }

        [TestCase("m_LocalRotation.x", true)]
        [TestCase("m_LocalRotation.w", true)]
        [TestCase("localEulerAnglesRaw.y", true)]
        [TestCase("m_LocalPosition.z", true)]
        [TestCase("m_LocalPosition.w", false)]
        [TestCase("m_LocalScale.x", false)]
        [TestCase("blendShape.Smile", false)]
        [TestCase("m_IsActive", false)]
        [TestCase("", false)]
        public void PosePropertiesAreRotationAndPosition(string property, bool pose)
        {
            Assert.That(ClipKeyReader.IsPoseProperty(property), Is.EqualTo(pose));
        }
    }
}
