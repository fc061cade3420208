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

        [TestCase(0.25)]
        [TestCase(1.0)]
        public void MaskedBonesKeepTheStreamsPoseTheOthersBlend(double w)
        {
            // Bone 1 is driven by a masked layer above the replaced one: it keeps the stream's rotation; bone 0 (and the root) blend.
            QuaternionD controller = Quaternions.FromAxisAngle(Vector3D.UnitX, 0.2);
            QuaternionD transition = Quaternions.FromAxisAngle(Vector3D.UnitX, 1.0);
            var pose = new double[8];
            transition.Write(pose, 0);
            transition.Write(pose, 4);
            var stream = new ArrayPoseStream(new double[] { 0, 2, 0 }, new double[8]);
            controller.Write(stream.Rotations, 0);
            controller.Write(stream.Rotations, 4);
            var shownRoot = new double[3];
            var shown = new double[8];
            PoseBlend.ApplyMasked(ref stream, w, new double[] { 1, 2, 3 }, pose, new[] { false, true }, shownRoot, shown);
            RotationAssert.SameRotation(QuaternionD.Read(stream.Rotations, 0), Quaternions.FromAxisAngle(Vector3D.UnitX, 0.2 + w * 0.8), 1e-12, "bone 0 blends");
            RotationAssert.SameRotation(QuaternionD.Read(stream.Rotations, 4), controller, 1e-12, "bone 1 is kept");
            Assert.That(shown, Is.EqualTo(stream.Rotations));
            Assert.That(shownRoot, Is.EqualTo(new[] { w, 2, 3 * w }));

            // With the root bone kept, the root position stays the stream's too.
            var kept = new ArrayPoseStream(new double[] { 0, 2, 0 }, new double[8]);
            controller.Write(kept.Rotations, 0);
            controller.Write(kept.Rotations, 4);
            PoseBlend.ApplyMasked(ref kept, w, new double[] { 1, 2, 3 }, pose, new[] { true, false }, shownRoot, shown);
            Assert.That(shownRoot, Is.EqualTo(new double[] { 0, 2, 0 }));
            RotationAssert.SameRotation(QuaternionD.Read(kept.Rotations, 0), controller, 1e-12, "root bone kept");
        }
    }
}
