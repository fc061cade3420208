using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Skeletons
{
    public class SkeletonTests
    {
        [Test]
        public void AcceptsAValidHierarchy()
        {
            var s = new Skeleton(new[] { "Hips", "Spine", "Head", "Leg" }, new[] { -1, 0, 1, 0 }, new double[12]);
            Assert.That(s.JointCount, Is.EqualTo(4));
            Assert.That(s.IndexOf("Head"), Is.EqualTo(2));
            Assert.That(s.IndexOf("Tail"), Is.EqualTo(-1));
        }

        [TestCase(new[] { 0, 0 }, "the root must come first")]
        [TestCase(new[] { -1, -1 }, "second root")]
        [TestCase(new[] { -1, 1 }, "listed before its children")]
        [TestCase(new[] { -1, 5 }, "listed before its children")]
        public void RejectsBadParents(int[] parents, string phrase)
        {
            Assert.That(() => new Skeleton(new[] { "a", "b" }, parents, new double[6]),
                Throws.ArgumentException.With.Message.Contains(phrase));
        }

        [Test]
        public void RejectsDuplicateAndEmptyNamesAndBadOffsets()
        {
            Assert.That(() => new Skeleton(new[] { "a", "a" }, new[] { -1, 0 }, new double[6]), Throws.ArgumentException.With.Message.Contains("must be unique"));
            Assert.That(() => new Skeleton(new[] { "a", " " }, new[] { -1, 0 }, new double[6]), Throws.ArgumentException.With.Message.Contains("empty name"));
            Assert.That(() => new Skeleton(new[] { "a", "b" }, new[] { -1, 0 }, new double[5]), Throws.ArgumentException.With.Message.Contains("3 per joint"));
            Assert.That(() => new Skeleton(new[] { "a" }, new[] { -1 }, new[] { 0, double.NaN, 0 }), Throws.ArgumentException.With.Message.Contains("not finite"));
            Assert.That(() => new Skeleton(new string[0], new int[0], new double[0]), Throws.ArgumentException);
        }

        [Test]
        public void MotionClipChecksItsArrays()
        {
            var s = new Skeleton(new[] { "a", "b" }, new[] { -1, 0 }, new double[] { 0, 0, 0, 1, 2, 3 });
            MotionClip rest = MotionClip.CreateRestPose(s, 3, 0.5);
            Assert.That(rest.Duration, Is.EqualTo(1.5));
            Assert.That(rest.LocalPositions[rest.PositionIndex(2, 1) + 2], Is.EqualTo(3));
            Assert.That(rest.LocalRotations[rest.RotationIndex(2, 1)], Is.EqualTo(1));
            Assert.That(() => new MotionClip(s, 3, 0.5, new double[17], new double[24]), Throws.ArgumentException);
            Assert.That(() => new MotionClip(s, 3, 0, new double[18], new double[24]), Throws.InstanceOf<System.ArgumentOutOfRangeException>());
        }
    }
}
