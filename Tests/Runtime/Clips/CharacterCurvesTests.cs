using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    /// <summary>The editor baker's conversions: a character's transforms ↔ its skeleton's motion, and the curves written from it.</summary>
    [TestFixture]
    public sealed class CharacterCurvesTests
    {
        private static CharacterRig Rig(RootFrame armature)
        {
            var rotations = new double[12];
            for (int b = 0; b < 3; b++) rotations[4 * b] = 1;
            return new CharacterRig("three", new[] { "Hips", "Spine", "Head" }, new[] { -1, 0, 1 }, new double[] { 0, 100, 0, 0, 20, 0, 0, 30, 0 }, rotations, armature);
        }

        [Test]
        public void UnityPosesRoundTripThroughTheSkeletonUnderAnArmature()
        {
            var armature = new RootFrame(new Vector3D(0.5, 0, 1), Quaternions.FromAxisAngle(new Vector3D(1, 0, 0), -Math.PI / 2), 0.01);
            CharacterRig rig = Rig(armature);
            var track = new CharacterPoseTrack(rig, 3, 1.0 / 30);
            var random = new Random(4);
            var root = new double[] { 1, 2, 95 };
            var rotations = new double[12];
            for (int b = 0; b < 3; b++)
            {
                var q = Quaternions.Normalize(new QuaternionD(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5));
                q.Write(rotations, 4 * b);
            }

            track.SetUnityPose(2, root, rotations);
            Assert.That(track.KeyFrames, Is.EqualTo(new[] { 2 }));
            // The root in the character: the armature turns and scales the bone's local position (centimetres → metres).
            Vector3D inCharacter = Handedness.PositionToUnity(Vector3D.Read(track.Motion.LocalPositions, track.Motion.PositionIndex(2, 0)));
            Vector3D want = armature.PointToParent(new Vector3D(1, 2, 95));
            Assert.That((inCharacter - want).Length, Is.LessThan(1e-12));

            var rootBack = new double[3];
            var rotationsBack = new double[12];
            CharacterPoseTrack.ReadUnityPose(rig, track.Motion, 2, rootBack, rotationsBack);
            for (int i = 0; i < 3; i++) Assert.That(rootBack[i], Is.EqualTo(root[i]).Within(1e-9));
            for (int b = 0; b < 3; b++)
            {
                double dot = 0;
                for (int c = 0; c < 4; c++) dot += rotations[4 * b + c] * rotationsBack[4 * b + c];
                Assert.That(Math.Abs(dot), Is.EqualTo(1).Within(1e-12), $"bone {b}");
            }

            // Frames without a key hold the reference pose.
            CharacterPoseTrack.ReadUnityPose(rig, track.Motion, 0, rootBack, rotationsBack);
            Assert.That(Math.Abs(rotationsBack[4]), Is.EqualTo(1).Within(1e-12));
        }

        [Test]
        public void GenericCurvesAreEveryBonesRotationInUnityOrderAndTheRootsPosition()
        {
            CharacterRig rig = Rig(RootFrame.Identity);
            var track = new CharacterPoseTrack(rig, 2, 0.5);
            var rotations = new double[] { 1, 0, 0, 0, 0.6, 0.8, 0, 0, 1, 0, 0, 0 };
            track.SetUnityPose(0, new double[] { 0, 1, 0 }, rotations);
            // The next frame is the same rotation negated: curves must not take the long way round.
            var negated = new double[12];
            for (int i = 0; i < 12; i++) negated[i] = -rotations[i];
            track.SetUnityPose(1, new double[] { 0, 1, 2 }, negated);
            IReadOnlyList<ClipCurve> curves = CurveBuilder.BuildCharacter(rig, track.Motion, new[] { "Armature/Hips", "Armature/Hips/Spine", "Armature/Hips/Spine/Head" });
            Assert.That(curves.Count, Is.EqualTo(3 * 4 + 3));
            ClipCurve spineX = curves[4];
            Assert.That(spineX.Path + ":" + spineX.Property, Is.EqualTo("Armature/Hips/Spine:m_LocalRotation.x"));
            Assert.That(spineX.Values, Is.EqualTo(new[] { 0.8f, 0.8f }).Within(1e-6f));
            Assert.That(curves[7].Property, Is.EqualTo("m_LocalRotation.w"));
            Assert.That(curves[7].Values, Is.EqualTo(new[] { 0.6f, 0.6f }).Within(1e-6f));
            Assert.That(curves[14].Path + ":" + curves[14].Property, Is.EqualTo("Armature/Hips:m_LocalPosition.z"));
            Assert.That(curves[14].Values, Is.EqualTo(new[] { 0f, 2f }).Within(1e-6f));
            Assert.That(curves[14].Times, Is.EqualTo(new[] { 0f, 0.5f }));
        }

        [TestCase("Spine Front-Back", "Spine Front-Back")]
        [TestCase("Left Arm Down-Up", "Left Arm Down-Up")]
        [TestCase("Left Index 1 Stretched", "LeftHand.Index.1 Stretched")]
        [TestCase("Right Thumb Spread", "RightHand.Thumb.Spread")]
        [TestCase("Right Little 3 Stretched", "RightHand.Little.3 Stretched")]
        public void MuscleCurvesAreNamedAsClipsNameThem(string muscle, string property)
        {
            Assert.That(HumanoidCurves.MuscleProperty(muscle), Is.EqualTo(property));
        }

        [Test]
        public void HumanoidCurvesHoldTheBodyAndEveryMuscleOnTheAnimator()
        {
            string[] muscles = { "Spine Front-Back", "Left Index 1 Stretched" };
            var positions = new float[] { 0, 1, 0, 0, 1, 0.5f };
            var rotations = new float[] { 0, 0, 0, 1, 0, 0, 0, -1 };
            var values = new float[] { 0.1f, -0.2f, 0.3f, -0.4f };
            IReadOnlyList<ClipCurve> curves = HumanoidCurves.Build(muscles, 1.0 / 30, positions, rotations, values);
            Assert.That(curves.Count, Is.EqualTo(3 + 4 + 2));
            foreach (ClipCurve c in curves) Assert.That(c.Path, Is.EqualTo(""));
            Assert.That(curves[2].Property, Is.EqualTo("RootT.z"));
            Assert.That(curves[2].Values, Is.EqualTo(new[] { 0f, 0.5f }));
            Assert.That(curves[6].Property, Is.EqualTo("RootQ.w"));
            Assert.That(curves[6].Values, Is.EqualTo(new[] { 1f, 1f }), "the body rotation stays in one hemisphere");
            Assert.That(curves[8].Property, Is.EqualTo("LeftHand.Index.1 Stretched"));
            Assert.That(curves[8].Values, Is.EqualTo(new[] { -0.2f, -0.4f }));
            var set = new HashSet<string> { "LeftHand.Index.1 Stretched" };
            Assert.That(HumanoidCurves.IsPoseProperty("RootQ.y", set), Is.True);
            Assert.That(HumanoidCurves.IsPoseProperty("LeftHand.Index.1 Stretched", set), Is.True);
            Assert.That(HumanoidCurves.IsPoseProperty("Speed", set), Is.False);
        }
    }
}
