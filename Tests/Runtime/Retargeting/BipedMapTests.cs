using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>Issue 30: the built-in 3ds Max Biped map (<c>Bip01_*</c>) on a Biped-shaped rig made here: thighs under the spine, clavicles under the neck, two spine links.</summary>
    public sealed class BipedMapTests
    {
        private static Skeleton BipedRig(Skeleton model)
        {
            ReferencePose t = ReferencePose.ModelTPose(model);
            Vector3D At(string name) => t.GlobalPosition(model.IndexOf(name));
            var joints = new List<(string Name, string? Parent, Vector3D At)>
            {
                ("Bip01", null, At("Hips")), ("Bip01_Pelvis", "Bip01", At("Hips")), ("Bip01_Spine", "Bip01_Pelvis", At("Spine")),
                ("Bip01_L_Thigh", "Bip01_Spine", At("LeftUpLeg")), ("Bip01_L_Calf", "Bip01_L_Thigh", At("LeftLeg")), ("Bip01_L_Foot", "Bip01_L_Calf", At("LeftFoot")), ("Bip01_L_Toe0", "Bip01_L_Foot", At("LeftToe")),
                ("Bip01_R_Thigh", "Bip01_Spine", At("RightUpLeg")), ("Bip01_R_Calf", "Bip01_R_Thigh", At("RightLeg")), ("Bip01_R_Foot", "Bip01_R_Calf", At("RightFoot")), ("Bip01_R_Toe0", "Bip01_R_Foot", At("RightToe")),
                ("Bip01_Spine1", "Bip01_Spine", At("Spine1")), ("Bip01_Spine2", "Bip01_Spine1", At("Spine2")), ("Bip01_Neck", "Bip01_Spine2", At("Neck")), ("Bip01_Head", "Bip01_Neck", At("Head")),
                ("Bip01_L_Clavicle", "Bip01_Neck", At("LeftShoulder")), ("Bip01_L_UpperArm", "Bip01_L_Clavicle", At("LeftArm")), ("Bip01_L_Forearm", "Bip01_L_UpperArm", At("LeftForeArm")), ("Bip01_L_Hand", "Bip01_L_Forearm", At("LeftHand")),
                ("Bip01_R_Clavicle", "Bip01_Neck", At("RightShoulder")), ("Bip01_R_UpperArm", "Bip01_R_Clavicle", At("RightArm")), ("Bip01_R_Forearm", "Bip01_R_UpperArm", At("RightForeArm")), ("Bip01_R_Hand", "Bip01_R_Forearm", At("RightHand")),
            };
            var names = new string[joints.Count];
            var parents = new int[joints.Count];
            var offsets = new double[3 * joints.Count];
            for (int j = 0; j < joints.Count; j++)
            {
                names[j] = joints[j].Name;
                parents[j] = joints[j].Parent == null ? -1 : Array.IndexOf(names, joints[j].Parent);
                (parents[j] < 0 ? joints[j].At : joints[j].At - joints[parents[j]].At).Write(offsets, 3 * j);
            }

            return new Skeleton(names, parents, offsets);
        }

        [Test]
        public void ABipedRigIsDetectedAndMapsBothWays()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            Skeleton biped = BipedRig(model);
            Assert.That(JointMap.Detect(biped, model), Is.SameAs(JointMap.Biped));
            Assert.That(JointMap.Named("biped"), Is.SameAs(JointMap.Biped));
            SkeletonMap map = SkeletonMap.Create(ReferencePose.Zero(biped), ReferencePose.ModelTPose(model), null, "biped.bvh");
            Assert.That(map.SynthesizedJoints, Is.EqualTo(new[] { "Spine2" }), "two spine links above Bip01_Spine: the model's third is made up");
            Assert.That(map.UnmappedSourceJoints, Is.EqualTo(new[] { "Bip01" }));
            BoneDirections.RequireTPose(map, ReferencePose.ModelTPose(model), BoneDirections.DefaultMaxDegrees, "biped.bvh");
            MotionClip motion = RetargetFixtures.Motion(ReferencePose.Zero(biped), 30, 1.0 / 30.0, 4, 2.0);
            MotionClip back = map.ToSource(map.ToTarget(motion), motion);
            double worst = 0;
            for (int f = 0; f < motion.FrameCount; f++)
            {
                for (int j = 0; j < model.JointCount; j++)
                {
                    if (map.IsSynthesized(j)) continue;
                    int s = map.SourceJointOf(j);
                    worst = Math.Max(worst, RetargetFixtures.Angle(QuaternionD.Read(motion.LocalRotations, motion.RotationIndex(f, s)), QuaternionD.Read(back.LocalRotations, back.RotationIndex(f, s))));
                }
            }

            TestContext.WriteLine($"largest mapped local-rotation error after model and back: {worst:E2} rad");
            Assert.That(worst, Is.LessThan(1e-9));
        }
    }
}
