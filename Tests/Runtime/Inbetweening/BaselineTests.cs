using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Inbetweening
{
    public class BaselineTests
    {
        private static Transition MakeTransition(int past, int missing, out QuaternionD start, out QuaternionD target)
        {
            var skeleton = new Skeleton(new[] { "root", "child" }, new[] { -1, 0 }, new double[] { 0, 0, 0, 0, 1, 0 });
            var t = new Transition(skeleton, past, missing);
            var random = new TestRandom(31);
            for (int k = 0; k < past + 1; k++)
            {
                random.Vector(10).Write(t.KeyRootPositions, 3 * k);
                random.Rotation().Write(t.KeyLocalRotations, 8 * k);
                random.Rotation().Write(t.KeyLocalRotations, 8 * k + 4);
            }

            new Vector3D(0, 0, 0).Write(t.KeyRootPositions, 3 * (past - 1));
            new Vector3D(4, 8, -4).Write(t.KeyRootPositions, 3 * past);
            start = Quaternions.FromAxisAngle(Vector3D.UnitY, 0.2);
            target = Quaternions.FromAxisAngle(Vector3D.UnitY, 1.8).Negated; // other hemisphere on purpose
            start.Write(t.KeyLocalRotations, 8 * (past - 1) + 4);
            target.Write(t.KeyLocalRotations, 8 * past + 4);
            return t;
        }

        [Test]
        public void ZeroVelocityRepeatsTheLastPastFrame()
        {
            Transition t = MakeTransition(10, 3, out QuaternionD start, out _);
            new ZeroVelocityBaseline().Inbetween(t);
            for (int k = 0; k < 3; k++)
            {
                Assert.That(Vector3D.Read(t.RootPositions, 3 * k), Is.EqualTo(new Vector3D(0, 0, 0)));
                Assert.That(QuaternionD.Read(t.LocalRotations, 8 * k + 4), Is.EqualTo(start));
            }
        }

        [Test]
        public void SlerpInterpolatesBetweenTheLastPastFrameAndTheTarget()
        {
            Transition t = MakeTransition(10, 3, out QuaternionD start, out QuaternionD target);
            new SlerpBaseline().Inbetween(t);
            for (int k = 0; k < 3; k++)
            {
                double a = (k + 1) / 4.0;
                Assert.That(SlerpBaseline.Weight(k, 3), Is.EqualTo(a));
                RotationAssert.SameVector(Vector3D.Read(t.RootPositions, 3 * k), new Vector3D(4 * a, 8 * a, -4 * a), 1e-14);
                // Constant angular speed about +Y on the short arc: 0.2 + a·1.6 rad.
                QuaternionD q = QuaternionD.Read(t.LocalRotations, 8 * k + 4);
                RotationAssert.SameRotation(q, Quaternions.FromAxisAngle(Vector3D.UnitY, 0.2 + a * 1.6), 1e-12);
                Assert.That(Quaternions.Dot(q, start), Is.GreaterThan(0), "stays in the first key's hemisphere");
                Assert.That(q.Length, Is.EqualTo(1).Within(1e-15));
                RotationAssert.SameRotation(q, Quaternions.Normalize(Quaternions.Slerp(start, target, a)), 1e-15);
            }
        }

        [Test]
        public void SlerpOfOneMissingFrameIsTheMidpoint()
        {
            Transition t = MakeTransition(1, 1, out _, out _);
            new SlerpBaseline().Inbetween(t);
            RotationAssert.SameVector(Vector3D.Read(t.RootPositions, 0), new Vector3D(2, 4, -2), 1e-15);
            RotationAssert.SameRotation(QuaternionD.Read(t.LocalRotations, 4), Quaternions.FromAxisAngle(Vector3D.UnitY, 1.0), 1e-12);
        }
    }
}
