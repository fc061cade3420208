using DeltaInterpolator.Core.Characters;
using System;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Rotations;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Characters
{
    [TestFixture]
    public sealed class NamePoseConverterTests
    {
        private static readonly Skeleton s_model = new Skeleton(new[] { "Hips", "Spine", "Head" }, new[] { -1, 0, 1 }, new double[] { 0, 90, 0, 0, 10, 0, 0, 20, 0 });

        [Test]
        public void ConvertsWithHandednessAndUnitsAndReordersBones()
        {
            var map = new NamePoseConverter(s_model, 0.01, new[] { "Head", "Hips", "Spine" });
            Assert.That(map.RootBone, Is.EqualTo(1));
            var random = new TestRandom(2);
            var boneRoot = new double[] { 0.3, 0.9, -1.2 };
            var boneRotations = new double[12];
            for (int b = 0; b < 3; b++) random.Rotation().Write(boneRotations, 4 * b);
            var jointRoot = new double[3];
            var jointRotations = new double[12];
            map.ToModel(boneRoot, boneRotations, jointRoot, jointRotations);
            // Unity metres → model centimetres, X mirrored; each joint takes its bone's rotation mirrored.
            RotationAssert.SameVector(Vector3D.Read(jointRoot, 0), new Vector3D(-30, 90, -120), 1e-9);
            Assert.That(QuaternionD.Read(jointRotations, 0), Is.EqualTo(Handedness.RotationFromUnity(QuaternionD.Read(boneRotations, 4))));
            Assert.That(QuaternionD.Read(jointRotations, 8), Is.EqualTo(Handedness.RotationFromUnity(QuaternionD.Read(boneRotations, 0))));

            var backRoot = new double[3];
            var backRotations = new double[12];
            map.ToCharacter(jointRoot, jointRotations, backRoot, backRotations);
            RotationAssert.SameVector(Vector3D.Read(backRoot, 0), Vector3D.Read(boneRoot, 0), 1e-12);
            Assert.That(backRotations, Is.EqualTo(boneRotations));
        }

        [Test]
        public void NamesThatDoNotMatchAreListed()
        {
            var e = Assert.Throws<ArgumentException>(() => new NamePoseConverter(s_model, 0.01, new[] { "Hips", "Chest", "Head" }));
            Assert.That(e!.Message, Does.Contain("not in the model: Chest").And.Contain("missing: Spine"));
            Assert.Throws<ArgumentException>(() => new NamePoseConverter(s_model, 0.01, new[] { "Hips", "Spine", "Head", "Hips" }));
        }
    }
}
