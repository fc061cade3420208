using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    public sealed class HandednessTests
    {
        [Test]
        public void EachPairRoundTrips()
        {
            var rng = new TestRandom(11);
            for (int i = 0; i < 200; i++)
            {
                Vector3D p = rng.Vector(100.0);
                QuaternionD q = rng.Rotation();
                Assert.That(Handedness.PositionFromUnity(Handedness.PositionToUnity(p)), Is.EqualTo(p));
                Assert.That(Handedness.PositionToUnity(Handedness.PositionFromUnity(p)), Is.EqualTo(p));
                Assert.That(Handedness.RotationFromUnity(Handedness.RotationToUnity(q)), Is.EqualTo(q));
                Assert.That(Handedness.RotationToUnity(Handedness.RotationFromUnity(q)), Is.EqualTo(q));
            }
        }

        [Test]
        public void ItIsAMirrorNotARotation()
        {
            // A mirror flips the sign of the triple product; a rotation would keep it.
            Vector3D a = Handedness.PositionToUnity(Vector3D.UnitX), b = Handedness.PositionToUnity(Vector3D.UnitY), c = Handedness.PositionToUnity(Vector3D.UnitZ);
            Assert.That(Vector3D.Dot(Vector3D.Cross(a, b), c), Is.EqualTo(-1.0));
        }

        [Test]
        public void RotatingAMirroredVectorByAMirroredRotationMirrorsTheRotatedVector()
        {
            var rng = new TestRandom(12);
            for (int i = 0; i < 200; i++)
            {
                Vector3D v = rng.Vector(10.0);
                QuaternionD q = rng.Rotation();
                Vector3D expected = Handedness.PositionToUnity(Quaternions.Apply(q, v));
                Vector3D actual = Quaternions.Apply(Handedness.RotationToUnity(q), Handedness.PositionToUnity(v));
                Assert.That((expected - actual).Length, Is.LessThan(1e-12));
            }
        }

        [Test]
        public void ForwardKinematicsOfMirroredRotationsGivesMirroredPositions()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            (Skeleton skeleton, ReferencePose reference) = RetargetFixtures.Source(model, 13, 1.0, 30.0);
            MotionClip clip = RetargetFixtures.Motion(reference, 20, 1.0 / 30.0, 14, 3.0);
            int j = skeleton.JointCount;

            // The same character in Unity space: offsets, root positions and rotations all mirrored.
            var offsets = new double[3 * j];
            for (int k = 0; k < j; k++) Handedness.PositionToUnity(Vector3D.Read(skeleton.OffsetSpan, 3 * k)).Write(offsets, 3 * k);
            var mirroredSkeleton = skeleton.WithOffsets(offsets);
            var positions = new double[clip.LocalPositions.Length];
            var rotations = new double[clip.LocalRotations.Length];
            for (int i = 0; i < clip.FrameCount * j; i++)
            {
                Handedness.PositionToUnity(Vector3D.Read(clip.LocalPositions, 3 * i)).Write(positions, 3 * i);
                Handedness.RotationToUnity(QuaternionD.Read(clip.LocalRotations, 4 * i)).Write(rotations, 4 * i);
            }

            var mirrored = new MotionClip(mirroredSkeleton, clip.FrameCount, clip.FrameTime, positions, rotations);
            double[] original = RetargetFixtures.GlobalPositions(clip);
            double[] inUnity = RetargetFixtures.GlobalPositions(mirrored);
            double worst = 0;
            for (int i = 0; i < clip.FrameCount * j; i++)
            {
                Vector3D expected = Handedness.PositionToUnity(Vector3D.Read(original, 3 * i));
                worst = System.Math.Max(worst, (expected - Vector3D.Read(inUnity, 3 * i)).Length);
            }

            Assert.That(worst, Is.LessThan(1e-9));
        }
    }
}
