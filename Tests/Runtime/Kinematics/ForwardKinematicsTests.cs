using System;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Kinematics
{
    public class ForwardKinematicsTests
    {
        private static readonly QuaternionD QuarterZ = Quaternions.FromAxisAngle(Vector3D.UnitZ, Math.PI / 2);

        [Test]
        public void ChainMatchesHandComputation()
        {
            // root at (1,2,3) turned 90° about Z; joint 1 one unit along its parent's X, turned 90° more;
            // joint 2 one unit along joint 1's X.
            // p1 = (1,2,3) + Rz90·(1,0,0) = (1,3,3); g1 = Rz180; p2 = (1,3,3) + Rz180·(1,0,0) = (0,3,3).
            var skeleton = new Skeleton(new[] { "root", "a", "b" }, new[] { -1, 0, 1 }, new double[] { 9, 9, 9, 1, 0, 0, 1, 0, 0 });
            double[] root = { 1, 2, 3 };
            var local = new double[12];
            QuarterZ.Write(local, 0);
            QuarterZ.Write(local, 4);
            QuaternionD.Identity.Write(local, 8);
            var gp = new double[9];
            var gr = new double[12];
            ForwardKinematics.Compute(skeleton, 1, root, local, gp, gr);
            Assert.That(gp, Is.EqualTo(new double[] { 1, 2, 3, 1, 3, 3, 0, 3, 3 }).Within(1e-14));
            RotationAssert.SameRotation(QuaternionD.Read(gr, 4), Quaternions.FromAxisAngle(Vector3D.UnitZ, Math.PI), 1e-15);
            RotationAssert.SameRotation(QuaternionD.Read(gr, 8), Quaternions.FromAxisAngle(Vector3D.UnitZ, Math.PI), 1e-15);
        }

        [Test]
        public void BranchesUseTheirOwnParent()
        {
            // root → a (offset +Y 2) and root → b (offset +X 3); a → c (offset +Y 1); a turned 90° about X.
            // a at (0,2,0); c = a + Rx90·(0,1,0) = (0,2,1); b at (3,0,0) unaffected by a's rotation.
            var skeleton = new Skeleton(new[] { "root", "a", "c", "b" }, new[] { -1, 0, 1, 0 }, new double[] { 0, 0, 0, 0, 2, 0, 0, 1, 0, 3, 0, 0 });
            var local = new double[16];
            QuaternionD.Identity.Write(local, 0);
            Quaternions.FromAxisAngle(Vector3D.UnitX, Math.PI / 2).Write(local, 4);
            QuaternionD.Identity.Write(local, 8);
            QuaternionD.Identity.Write(local, 12);
            var gp = new double[12];
            var gr = new double[16];
            ForwardKinematics.Compute(skeleton, 1, new double[3], local, gp, gr);
            Assert.That(gp, Is.EqualTo(new double[] { 0, 0, 0, 0, 2, 0, 0, 2, 1, 3, 0, 0 }).Within(1e-14));
        }

        [Test]
        public void LocalPositionsVariantUsesPerFrameTranslations()
        {
            var skeleton = new Skeleton(new[] { "root", "a" }, new[] { -1, 0 }, new double[] { 0, 0, 0, 1, 0, 0 });
            double[] localPositions = { 5, 0, 0, 0, 7, 0, /* frame 1 */ 0, 1, 0, 2, 0, 0 };
            var local = new double[16];
            for (int i = 0; i < 4; i++) QuarterZ.Write(local, 4 * i);
            var gp = new double[12];
            var gr = new double[16];
            ForwardKinematics.ComputeWithLocalPositions(skeleton, 2, localPositions, local, gp, gr);
            // frame 0: a = (5,0,0) + Rz90·(0,7,0) = (−2,0,0); frame 1: a = (0,1,0) + Rz90·(2,0,0) = (0,3,0)
            Assert.That(gp, Is.EqualTo(new double[] { 5, 0, 0, -2, 0, 0, 0, 1, 0, 0, 3, 0 }).Within(1e-14));
        }
    }
}
