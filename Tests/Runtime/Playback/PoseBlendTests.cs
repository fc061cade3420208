using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Playback
{
    [TestFixture]
    public sealed class PoseBlendTests
    {
        [Test]
        public void WeightZeroKeepsTheStreamOneShowsThePoseBetweenSlerps()
        {
            QuaternionD controller = Quaternions.FromAxisAngle(Vector3D.UnitX, 0.2);
            QuaternionD transition = Quaternions.FromAxisAngle(Vector3D.UnitX, 1.0);
            var pose = new double[4];
            transition.Write(pose, 0);
            var poseRoot = new double[] { 1, 2, 3 };
            var shownRoot = new double[3];
            var shown = new double[4];
            foreach (double w in new[] { 0.0, 0.25, 1.0 })
            {
                var stream = new ArrayPoseStream(new double[] { 0, 2, 0 }, new double[4]);
                controller.Write(stream.Rotations, 0);
                PoseBlend.Apply(ref stream, w, poseRoot, pose, shownRoot, shown);
                QuaternionD expected = Quaternions.FromAxisAngle(Vector3D.UnitX, 0.2 + w * 0.8);
                RotationAssert.SameRotation(QuaternionD.Read(stream.Rotations, 0), expected, 1e-12, $"w = {w}");
                Assert.That(shown, Is.EqualTo(stream.Rotations));
                Assert.That(shownRoot, Is.EqualTo(new[] { w, 2, 3 * w }));
                Assert.That(stream.Root, Is.EqualTo(shownRoot));
            }
        }
    }
}
