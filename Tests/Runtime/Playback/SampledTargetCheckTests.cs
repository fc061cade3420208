using System;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// The humanoid target check's comparison (<see cref="SampledTargetCheck"/>): a target read one way against the same
    /// clip frame read by <c>AnimationClip.SampleAnimation</c>; the root bone's rotation is the root motion's, not compared.
    /// </summary>
    [TestFixture]
    public sealed class SampledTargetCheckTests
    {
        private static double[] Pose(params (Vector3D Axis, double Degrees)[] bones)
        {
            var values = new double[4 * bones.Length];
            for (int b = 0; b < bones.Length; b++) Quaternions.FromAxisAngle(bones[b].Axis, bones[b].Degrees * Math.PI / 180).Write(values, 4 * b);
            return values;
        }

        [Test]
        public void AgreeingReadsSayNothingAndTheRootIsLeftOut()
        {
            double[] read = Pose((Vector3D.UnitY, 90), (Vector3D.UnitX, 20), (Vector3D.UnitZ, -35));
            double[] reference = Pose((Vector3D.UnitY, 0), (Vector3D.UnitX, 20.5), (Vector3D.UnitZ, -35));
            // A quaternion and its negation are the same rotation.
            for (int i = 8; i < 12; i++) reference[i] = -reference[i];
            Assert.That(SampledTargetCheck.Compare(read, reference, "walk", 1.5, b => "bone" + b), Is.Null);
            Assert.That(SampledTargetCheck.LargestDifference(read, reference).Bone, Is.EqualTo(1));
            Assert.That(SampledTargetCheck.LargestDifference(read, reference).Degrees, Is.EqualTo(0.5).Within(1e-9));
        }

        [Test]
        public void ADifferingBoneIsNamedWithItsAngle()
        {
            double[] read = Pose((Vector3D.UnitY, 0), (Vector3D.UnitX, 20), (Vector3D.UnitZ, -35));
            double[] reference = Pose((Vector3D.UnitY, 0), (Vector3D.UnitX, 20), (Vector3D.UnitZ, -30));
            string? message = SampledTargetCheck.Compare(read, reference, "walk", 1.5, b => b == 2 ? "LeftUpperArm" : "other");
            Assert.That(message, Does.Contain("clip 'walk' at 1.5 s").And.Contain("by 5° at bone LeftUpperArm"));
        }

        [Test]
        public void PosesOfDifferentLengthsAreRefusedNamingTheArgument()
        {
            var e = Assert.Throws<ArgumentException>(() => SampledTargetCheck.LargestDifference(new double[8], new double[12]));
            Assert.That(e!.ParamName, Is.EqualTo("reference"));
        }
    }
}
