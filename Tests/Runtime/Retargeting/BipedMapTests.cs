using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>Issue 30: the built-in 3ds Max Biped maps (<c>Bip01_*</c>) on Biped-shaped rigs made here: thighs under the spine or the pelvis, clavicles under the neck, two spine links above the first.</summary>
    public sealed class BipedMapTests
    {
        internal static Skeleton BipedRig(Skeleton model, string thighParent = "Bip01_Spine")
        {
            ReferencePose t = ReferencePose.ModelTPose(model);
            Vector3D At(string name) => t.GlobalPosition(model.IndexOf(name));
            // Listed depth first, as a BVH file holds them: the legs before the spine when they hang under the pelvis.
            var legs = new List<(string Name, string? Parent, Vector3D At)>
            {
                ("Bip01_L_Thigh", thighParent, At("LeftUpLeg")), ("Bip01_L_Calf", "Bip01_L_Thigh", At("LeftLeg")), ("Bip01_L_Foot", "Bip01_L_Calf", At("LeftFoot")), ("Bip01_L_Toe0", "Bip01_L_Foot", At("LeftToe")),
                ("Bip01_R_Thigh", thighParent, At("RightUpLeg")), ("Bip01_R_Calf", "Bip01_R_Thigh", At("RightLeg")), ("Bip01_R_Foot", "Bip01_R_Calf", At("RightFoot")), ("Bip01_R_Toe0", "Bip01_R_Foot", At("RightToe")),
            };
            var joints = new List<(string Name, string? Parent, Vector3D At)> { ("Bip01", null, At("Hips")), ("Bip01_Pelvis", "Bip01", At("Hips")) };
            if (thighParent == "Bip01_Pelvis") joints.AddRange(legs);
            joints.Add(("Bip01_Spine", "Bip01_Pelvis", At("Spine")));
            if (thighParent != "Bip01_Pelvis") joints.AddRange(legs);
            joints.AddRange(new List<(string Name, string? Parent, Vector3D At)>
            {
                ("Bip01_Spine1", "Bip01_Spine", At("Spine1")), ("Bip01_Spine2", "Bip01_Spine1", At("Spine2")), ("Bip01_Neck", "Bip01_Spine2", At("Neck")), ("Bip01_Head", "Bip01_Neck", At("Head")),
                ("Bip01_L_Clavicle", "Bip01_Neck", At("LeftShoulder")), ("Bip01_L_UpperArm", "Bip01_L_Clavicle", At("LeftArm")), ("Bip01_L_Forearm", "Bip01_L_UpperArm", At("LeftForeArm")), ("Bip01_L_Hand", "Bip01_L_Forearm", At("LeftHand")),
                ("Bip01_R_Clavicle", "Bip01_Neck", At("RightShoulder")), ("Bip01_R_UpperArm", "Bip01_R_Clavicle", At("RightArm")), ("Bip01_R_Forearm", "Bip01_R_UpperArm", At("RightForeArm")), ("Bip01_R_Hand", "Bip01_R_Forearm", At("RightHand")),
            });
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

        /// <summary>
        /// Both layouts Biped writes: thighs under <c>Bip01_Spine</c> (the classic link; two spine links above it, so the
        /// model's third spine joint is made up) and thighs under <c>Bip01_Pelvis</c> (Triangle Pelvis; the pelvis alone
        /// plays the hips and Spine..Spine2 are Biped's three links). The first map alone refused the second layout
        /// ("'LeftUpLeg' maps to 'Bip01_L_Thigh', which is not below 'Bip01_Spine'").
        /// </summary>
        [TestCase("Bip01_Spine", "biped", new[] { "Spine2" })]
        [TestCase("Bip01_Pelvis", "biped-pelvis", new string[0])]
        public void ABipedRigIsDetectedAndMapsBothWays(string thighParent, string mapName, string[] madeUp)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            Skeleton biped = BipedRig(model, thighParent);
            Assert.That(JointMap.Detect(biped, model).Name, Is.EqualTo(mapName));
            Assert.That(JointMap.Named(mapName), Is.SameAs(JointMap.Detect(biped, model)));
            SkeletonMap map = SkeletonMap.Create(ReferencePose.Zero(biped), ReferencePose.ModelTPose(model), null, "biped.bvh");
            Assert.That(map.SynthesizedJoints, Is.EqualTo(madeUp));
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
