using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    public sealed class ReferencePoseTests
    {
        private static Vector3D Bone(ReferencePose pose, string from, string to)
        {
            Skeleton s = pose.Skeleton;
            Vector3D v = pose.GlobalPosition(s.IndexOf(to)) - pose.GlobalPosition(s.IndexOf(from));
            return (1.0 / v.Length) * v;
        }

        [Test]
        public void TheModelsTPoseStandsFacingPlusZWithArmsOut()
        {
            ReferencePose t = ReferencePose.ModelTPose(RetargetFixtures.Lafan1());
            Vector3D down = new Vector3D(0, -1, 0);
            Assert.That((Bone(t, "LeftUpLeg", "LeftLeg") - down).Length, Is.LessThan(1e-9));
            Assert.That((Bone(t, "RightLeg", "RightFoot") - down).Length, Is.LessThan(1e-9));
            Assert.That((Bone(t, "Spine1", "Spine2") - Vector3D.UnitY).Length, Is.LessThan(1e-9));
            Assert.That((Bone(t, "Neck", "Head") - Vector3D.UnitY).Length, Is.LessThan(1e-9));
            Assert.That((Bone(t, "LeftArm", "LeftForeArm") - Vector3D.UnitX).Length, Is.LessThan(1e-9));
            Assert.That((Bone(t, "RightForeArm", "RightHand") - new Vector3D(-1, 0, 0)).Length, Is.LessThan(1e-9));
            // The foot bone (ankle → toe) points forward, 30° down.
            Assert.That((Bone(t, "LeftFoot", "LeftToe") - new Vector3D(0, -0.5, System.Math.Sqrt(0.75))).Length, Is.LessThan(1e-9));
            // The left hip is on the +X side; the model's facing axis (hips' local +Y) points along +Z.
            Assert.That(t.GlobalPosition(1).X, Is.GreaterThan(t.GlobalPosition(5).X));
            Assert.That((Quaternions.Apply(t.GlobalRotation(0), Vector3D.UnitY) - Vector3D.UnitZ).Length, Is.LessThan(1e-9));
            // Feet on the ground: the lowest joint at height 0.
            double lowest = double.MaxValue;
            for (int j = 0; j < 22; j++) lowest = System.Math.Min(lowest, t.GlobalPosition(j).Y);
            Assert.That(lowest, Is.EqualTo(0.0).Within(1e-9));
        }

        [Test]
        public void FromFrameTakesThatFramesPose()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            MotionClip clip = RetargetFixtures.Motion(ReferencePose.ModelTPose(model), 5, 1.0 / 30.0, 31, 1.0);
            ReferencePose p = ReferencePose.FromFrame(clip, 3);
            Assert.That(p.RootPosition, Is.EqualTo(Vector3D.Read(clip.LocalPositions, clip.PositionIndex(3, 0))));
            Assert.That(RetargetFixtures.Angle(QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(3, 9)), new QuaternionD(p.LocalRotations[36], p.LocalRotations[37], p.LocalRotations[38], p.LocalRotations[39])), Is.LessThan(1e-12));
            Assert.Throws<System.ArgumentOutOfRangeException>(() => ReferencePose.FromFrame(clip, 5));
        }
    }
}
