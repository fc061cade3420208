using System;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// <see cref="RootMotionFrameCheck"/> on its own: what counts as evidence for the frame of the stream's velocity
    /// (the frame loop is <c>RootMotionFrameTests</c>).
    /// </summary>
    [TestFixture]
    public sealed class RootMotionFrameCheckTests
    {
        private static readonly QuaternionD Turned60 = Quaternions.FromAxisAngle(Vector3D.UnitY, Math.PI / 3);

        [Test]
        public void ACharacterFacingTheWorldsAxesIsNoEvidence()
        {
            var check = new RootMotionFrameCheck();
            var v = new Vector3D(0, 0, 1.5);
            for (int i = 0; i < 50; i++) Assert.That(check.Observe(v, v, QuaternionD.Identity), Is.Null);
            Assert.That(check.Decided, Is.False);
            Assert.That(check.Frame, Is.EqualTo(RootVelocityFrame.Local), "the evidence-backed default");
        }

        [TestCase(RootVelocityFrame.Local)]
        [TestCase(RootVelocityFrame.World)]
        public void FiveAgreeingFramesInARowDecide(RootVelocityFrame engine)
        {
            var check = new RootMotionFrameCheck(engine == RootVelocityFrame.Local ? RootVelocityFrame.World : RootVelocityFrame.Local);
            var local = new Vector3D(0.1, 0, 1.2);
            Vector3D world = Quaternions.Apply(Turned60, local);
            Vector3D stream = engine == RootVelocityFrame.Local ? local : world;
            for (int i = 0; i < RootMotionFrameCheck.FramesOfEvidence - 1; i++) check.Observe(stream, world, Turned60);
            Assert.That(check.Decided, Is.False, "four frames are not enough");
            check.Observe(stream, world, Turned60);
            Assert.That(check.Decided, Is.True);
            Assert.That(check.Frame, Is.EqualTo(engine));
            Vector3D back = check.ToWorld(check.ToStream(world, Turned60), Turned60);
            Assert.That((back - world).Length, Is.LessThan(1e-12));
        }

        [Test]
        public void SlowAndNonFiniteFramesAreNoEvidenceAndAMismatchSaysSoOnce()
        {
            var check = new RootMotionFrameCheck();
            var stream = new Vector3D(0, 0, 1);
            Vector3D opposite = Quaternions.Apply(Turned60, new Vector3D(0, 0, -1));
            Assert.That(check.Observe(new Vector3D(0, 0, 0.01), opposite, Turned60), Is.Null);
            Assert.That(check.Observe(new Vector3D(double.NaN, 0, 1), opposite, Turned60), Is.Null);
            Assert.That(check.Observe(new Vector3D(double.PositiveInfinity, 0, 1), opposite, Turned60), Is.Null);
            int said = 0;
            for (int i = 0; i < 20; i++) if (check.Observe(stream, opposite, Turned60) != null) said++;
            Assert.That(said, Is.EqualTo(1));
            Assert.That(check.NeitherMatched, Is.True);
            Assert.That(check.Decided, Is.False);
        }
    }
}
