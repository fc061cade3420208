using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Retargeting;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Characters
{
    /// <summary>
    /// A humanoid character (HumanBodyBones names, Unity space, metres) mapped to the model's skeleton with
    /// <see cref="JointMap.UnityHumanoid"/>: poses go to the model and come back unchanged.
    /// </summary>
    [TestFixture]
    public sealed class SkeletonPoseConverterTests
    {
        // The LaFAN1 skeleton as a Unity humanoid rig: HumanBodyBones names, metres, Unity's handedness,
        // with its T-pose as the reference.
        private static SkeletonPoseConverter Humanoid(Skeleton model)
        {
            int n = model.JointCount;
            var names = new List<string>();
            var positions = new double[3 * n];
            var rotations = new double[4 * n];
            double[] offsets = Copy(model.Offsets);
            double[] tposeRotations = Copy(ReferencePose.ModelTPose(model).LocalRotations);
            for (int j = 0; j < n; j++)
            {
                IReadOnlyList<string> chain = JointMap.UnityHumanoid.SourceChain(model.Names[j])!;
                names.Add(chain[chain.Count - 1]);
                Handedness.PositionToUnity(0.01 * Vector3D.Read(offsets, 3 * j)).Write(positions, 3 * j);
                Handedness.RotationToUnity(QuaternionD.Read(tposeRotations, 4 * j)).Write(rotations, 4 * j);
            }

            return SkeletonPoseConverter.FromUnity(names, model.Parents, positions, rotations, model, "humanoid");
        }

        private static double[] Copy(IReadOnlyList<double> values)
        {
            var a = new double[values.Count];
            for (int i = 0; i < a.Length; i++) a[i] = values[i];
            return a;
        }

        [Test]
        public void AHumanoidPoseRoundTripsThroughTheModel()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            SkeletonPoseConverter map = Humanoid(model);
            Assert.That(map.BoneCount, Is.EqualTo(model.JointCount));
            Assert.That(map.JointCount, Is.EqualTo(model.JointCount));
            // Centimetres against metres, same proportions: the root scales by 100.
            Assert.That(map.Map.RootScale, Is.EqualTo(100).Within(1e-9));

            var random = new Random(7);
            int n = map.BoneCount;
            var boneRoot = new[] { 0.3, 0.9, -1.2 };
            var bones = new double[4 * n];
            for (int b = 0; b < n; b++)
            {
                var q = new QuaternionD(random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1, random.NextDouble() * 2 - 1);
                Quaternions.Normalize(q).Write(bones, 4 * b);
            }

            var jointRoot = new double[3];
            var joints = new double[4 * n];
            map.ToModel(boneRoot, bones, jointRoot, joints);
            // Unity X is mirrored into the model's right-handed space, and metres become centimetres.
            Assert.That(jointRoot, Is.EqualTo(new[] { -30.0, 90.0, -120.0 }).Within(1e-9));

            var backRoot = new double[3];
            var back = new double[4 * n];
            map.ToCharacter(jointRoot, joints, backRoot, back);
            Assert.That(backRoot, Is.EqualTo(boneRoot).Within(1e-9));
            for (int b = 0; b < n; b++)
            {
                double dot = 0;
                for (int k = 0; k < 4; k++) dot += bones[4 * b + k] * back[4 * b + k];
                Assert.That(Math.Abs(dot), Is.EqualTo(1).Within(1e-9), $"bone {b} ({map.Map.Source.Names[b]})");
            }
        }

        [Test]
        public void ARigMissingAModelJointIsRefused()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            int n = model.JointCount;
            var names = new List<string>(model.Names); // LaFAN1 names are not HumanBodyBones names
            var rotations = new double[4 * n];
            for (int b = 0; b < n; b++) rotations[4 * b] = 1;
            Assert.Throws<JointMapException>(() => SkeletonPoseConverter.FromUnity(names, model.Parents, Copy(model.Offsets), rotations, model, "rig"));
        }
    }
}
