using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    public sealed class MotionResamplerTests
    {
        private static MotionClip Clip(int frames, double frameTime)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            return RetargetFixtures.Motion(ReferencePose.ModelTPose(model), frames, frameTime, 21, 2.0);
        }

        [Test]
        public void From120To30KeepsEveryFourthFrameExactly()
        {
            MotionClip clip = Clip(121, 1.0 / 120.0);
            MotionClip at30 = MotionResampler.Resample(clip, 1.0 / 30.0);
            Assert.That(at30.FrameCount, Is.EqualTo(31));
            int j = clip.Skeleton.JointCount;
            for (int f = 0; f < at30.FrameCount; f++)
            {
                for (int k = 0; k < j; k++)
                {
                    Assert.That(RetargetFixtures.Angle(QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(4 * f, k)), QuaternionD.Read(at30.LocalRotations, at30.RotationIndex(f, k))), Is.LessThan(1e-12));
                }

                Assert.That((Vector3D.Read(clip.LocalPositions, clip.PositionIndex(4 * f, 0)) - Vector3D.Read(at30.LocalPositions, at30.PositionIndex(f, 0))).Length, Is.LessThan(1e-12));
            }
        }

        [Test]
        public void UpsamplingSlerpsRotationsAndLerpsTheRoot()
        {
            MotionClip clip = Clip(10, 1.0 / 30.0);
            MotionClip at120 = MotionResampler.Resample(clip, 1.0 / 120.0);
            Assert.That(at120.FrameCount, Is.EqualTo(37));
            int joint = 7;
            QuaternionD a = QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(3, joint));
            QuaternionD b = QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(4, joint));
            for (int i = 0; i <= 4; i++)
            {
                QuaternionD expected = Quaternions.Normalize(Quaternions.Slerp(a, b, i / 4.0));
                Assert.That(RetargetFixtures.Angle(expected, QuaternionD.Read(at120.LocalRotations, at120.RotationIndex(12 + i, joint))), Is.LessThan(1e-9));
            }

            Vector3D r3 = Vector3D.Read(clip.LocalPositions, clip.PositionIndex(3, 0)), r4 = Vector3D.Read(clip.LocalPositions, clip.PositionIndex(4, 0));
            Vector3D mid = Vector3D.Read(at120.LocalPositions, at120.PositionIndex(14, 0));
            Assert.That((mid - (0.5 * (r3 + r4))).Length, Is.LessThan(1e-12));
        }
    }
}
