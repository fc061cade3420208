using System;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Kinematics
{
    public class FacingTests
    {
        [Test]
        public void YawTowardTurnsTheFacingOntoTheTargetAboutY()
        {
            var random = new TestRandom(5);
            for (int trial = 0; trial < 100; trial++)
            {
                QuaternionD root = random.Rotation();
                QuaternionD yaw = Facing.YawToward(root, Vector3D.UnitY, Vector3D.UnitX);
                Assert.That(yaw.X, Is.EqualTo(0).Within(1e-15), "a rotation about +Y only");
                Assert.That(yaw.Z, Is.EqualTo(0).Within(1e-15), "a rotation about +Y only");
                Vector3D forward = Quaternions.Apply(Quaternions.Multiply(yaw, root), Vector3D.UnitY);
                Assert.That(forward.Z, Is.EqualTo(0).Within(1e-12), "no sideways component after the yaw");
                Assert.That(forward.X, Is.GreaterThan(0), "faces +X, not −X");
            }
        }

        [Test]
        public void FacingExactlyBackwardsIsAHalfTurnNotACollapse()
        {
            // Hips +Y pointing to −X: official quat_between would give a zero quaternion here.
            QuaternionD q = Quaternions.FromAxisAngle(Vector3D.UnitZ, Math.PI / 2); // +Y → −X
            QuaternionD yaw = Facing.YawToward(q, Vector3D.UnitY, Vector3D.UnitX);
            Assert.That(yaw.Length, Is.EqualTo(1.0).Within(1e-15));
            RotationAssert.SameRotation(yaw, Quaternions.FromAxisAngle(Vector3D.UnitY, Math.PI), 1e-12);
        }

        [Test]
        public void VerticalFacingGivesTheIdentityYaw()
        {
            // Hips' local +Y pointing straight up: no horizontal facing to align.
            Assert.That(Facing.YawToward(QuaternionD.Identity, Vector3D.UnitY, Vector3D.UnitX), Is.EqualTo(QuaternionD.Identity));
            QuaternionD nearlyUp = Quaternions.FromAxisAngle(Vector3D.UnitZ, 1e-7);
            Assert.That(Facing.YawToward(nearlyUp, Vector3D.UnitY, Vector3D.UnitX), Is.EqualTo(QuaternionD.Identity), "horizontal part below 1e-6");
        }
    }
}
