using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Kinematics
{
    public class WindowNormalizationTests
    {
        [Test]
        public void CenterXZRemovesTheMeanButKeepsHeight()
        {
            double[] root = { 1, 10, 5, 3, 20, 7, 5, 30, 9 };
            WindowNormalization.CenterXZ(root, 3);
            Assert.That(root, Is.EqualTo(new double[] { -2, 10, -2, 0, 20, 0, 2, 30, 2 }).Within(1e-15));
        }

        [Test]
        public void FaceAxisTurnsTheFacingFrameToPlusX()
        {
            var random = new TestRandom(21);
            for (int trial = 0; trial < 100; trial++)
            {
                const int frames = 12, joints = 2;
                var root = new double[frames * 3];
                var rotations = new double[frames * joints * 4];
                for (int f = 0; f < frames; f++)
                {
                    random.Vector(100).Write(root, 3 * f);
                    random.Rotation().Write(rotations, f * joints * 4);
                    random.Rotation().Write(rotations, f * joints * 4 + 4);
                }

                double[] rootBefore = (double[])root.Clone();
                double[] rotationsBefore = (double[])rotations.Clone();
                WindowNormalization.FaceAxis(root, rotations, frames, joints, 9, Vector3D.UnitY, Vector3D.UnitX);

                Vector3D forward = Quaternions.Apply(QuaternionD.Read(rotations, 9 * joints * 4), Vector3D.UnitY);
                Assert.That(forward.Z, Is.EqualTo(0).Within(1e-12), "no sideways component at the facing frame");
                Assert.That(forward.X, Is.GreaterThan(0), "faces +X, not −X");
                for (int f = 0; f < frames; f++)
                {
                    Vector3D before = Vector3D.Read(rootBefore, 3 * f), after = Vector3D.Read(root, 3 * f);
                    Assert.That(after.Y, Is.EqualTo(before.Y).Within(1e-12), "a yaw keeps heights");
                    Assert.That(after.Length, Is.EqualTo(before.Length).Within(1e-9), "a rotation about the origin keeps distances");
                    Assert.That(rotations[f * joints * 4 + 4], Is.EqualTo(rotationsBefore[f * joints * 4 + 4]), "non-root local rotations are untouched");
                }
            }
        }
    }
}
