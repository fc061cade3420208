using DeltaInterpolator.Core.Characters;
using System.Collections.Generic;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Characters
{
    /// <summary>Which transforms a character's component drives: the mapped bones, the bones between them, nothing else.</summary>
    [TestFixture]
    public sealed class RigBoneSelectionTests
    {
        // An FBX-like hierarchy: an armature, the hips, a twist bone, an unnamed neck joint, fingers, a prop.
        private static readonly string[] Names =
        {
            "Armature", "mixamorig:Hips", "mixamorig:Spine", "mixamorig:Neck", "neck_extra", "mixamorig:Head", "mixamorig:LeftUpLeg", "thigh_twist_l",
            "mixamorig:LeftLeg", "mixamorig:LeftHandIndex1", "Sword",
        };

        private static readonly int[] Parents = { -1, 0, 1, 2, 3, 4, 1, 6, 6, 8, -1 };

        [Test]
        public void DrivesMappedBonesAndTheBonesBetweenThemOnly()
        {
            var roles = new string?[Names.Length];
            roles[1] = "Hips";
            roles[2] = "Spine";
            roles[3] = "Neck";
            roles[5] = "Head";
            roles[6] = "LeftUpperLeg";
            roles[8] = "LeftLowerLeg";
            RigBoneSelection s = RigBoneSelection.Select(Names, Parents, roles, 1, "Hips", "hero");
            Assert.That(s.Transforms, Is.EqualTo(new[] { 1, 2, 3, 4, 5, 6, 8 }), "not the armature, the twist bone, the finger or the prop");
            Assert.That(s.BoneNames, Is.EqualTo(new[] { "Hips", "Spine", "Neck", "neck_extra", "Head", "LeftUpperLeg", "LeftLowerLeg" }));
            Assert.That(s.Parents, Is.EqualTo(new[] { -1, 0, 1, 2, 3, 0, 5 }));
        }

        [Test]
        public void AMappedBoneOutsideTheHipsIsRefusedNamingIt()
        {
            var roles = new string?[Names.Length];
            roles[1] = "Hips";
            roles[10] = "RightHand";
            var error = Assert.Throws<JointMapException>(() => RigBoneSelection.Select(Names, Parents, roles, 1, "Hips", "hero"));
            Assert.That(error!.Message, Does.Contain("RightHand ('Sword')"));
            Assert.Throws<JointMapException>(() => RigBoneSelection.Select(Names, Parents, new string?[Names.Length], -1, "Hips", "hero"));
        }

        [Test]
        public void AJointMapFindsBonesByNameIgnoringNamespacesAndRenamesOverrideIt()
        {
            JointMap map = JointMap.Mixamo.WithBones(new[] { new KeyValuePair<string, string>("LeftLeg", "thigh_twist_l") });
            string?[] roles = RigBoneSelection.RolesFromJointMap(Names, map, "Hips", "hero", out int root);
            Assert.That(root, Is.EqualTo(1));
            Assert.That(roles[1], Is.EqualTo("mixamorig:Hips"));
            Assert.That(roles[7], Is.EqualTo("thigh_twist_l"));
            Assert.That(roles[8], Is.Null, "renamed away");
            Assert.That(roles[4], Is.Null);
            var twice = new List<string>(Names) { "mixamorig:Head" };
            var error = Assert.Throws<JointMapException>(() => RigBoneSelection.RolesFromJointMap(twice, JointMap.Mixamo, "Hips", "hero", out _));
            Assert.That(error!.Message, Does.Contain("'Head'"));
        }
    }
}
