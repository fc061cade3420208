using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEngine;

namespace DeltaInterpolator.Tests.Unity
{
    /// <summary>
    /// The bone mask of a masked layer above: which driven bones an <c>AvatarMask</c> lets that layer drive (they keep its pose
    /// during a neural transition). EditMode tests on real GameObjects; the Unity check compiles them.
    /// </summary>
    public sealed class AvatarMaskBonesTests
    {
        [Test]
        public void HumanoidBonesFallInTheMaskInspectorsBodyParts()
        {
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.Hips), Is.EqualTo(AvatarMaskBodyPart.Body));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.UpperChest), Is.EqualTo(AvatarMaskBodyPart.Body));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.Neck), Is.EqualTo(AvatarMaskBodyPart.Head));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.LeftShoulder), Is.EqualTo(AvatarMaskBodyPart.LeftArm));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.RightHand), Is.EqualTo(AvatarMaskBodyPart.RightArm));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.LeftToes), Is.EqualTo(AvatarMaskBodyPart.LeftLeg));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.RightLowerLeg), Is.EqualTo(AvatarMaskBodyPart.RightLeg));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.LeftLittleDistal), Is.EqualTo(AvatarMaskBodyPart.LeftFingers));
            Assert.That(AvatarMaskBones.BodyPart(HumanBodyBones.RightThumbProximal), Is.EqualTo(AvatarMaskBodyPart.RightFingers));
        }

        [Test]
        public void AGenericMaskSelectsBonesByTheirPathUnderTheAnimator()
        {
            var character = new GameObject("Character");
            try
            {
                Animator animator = character.AddComponent<Animator>();
                Transform hips = Child(character.transform, "Hips");
                Transform spine = Child(hips, "Spine");
                Transform arm = Child(spine, "LeftArm");
                Transform leg = Child(hips, "LeftUpLeg");
                var mask = new AvatarMask();
                mask.transformCount = 4;
                mask.SetTransformPath(0, "Hips");
                mask.SetTransformActive(0, false);
                mask.SetTransformPath(1, "Hips/Spine");
                mask.SetTransformActive(1, true);
                mask.SetTransformPath(2, "Hips/Spine/LeftArm");
                mask.SetTransformActive(2, true);
                mask.SetTransformPath(3, "Hips/LeftUpLeg");
                mask.SetTransformActive(3, false);
                bool[] active = AvatarMaskBones.Active(mask, animator, new[] { hips, spine, arm, leg });
                Assert.That(active, Is.EqualTo(new[] { false, true, true, false }));
                Object.DestroyImmediate(mask);
            }
            finally
            {
                Object.DestroyImmediate(character);
            }
        }

        [Test]
        public void AMaskWithoutTransformsLetsEveryGenericBoneThrough()
        {
            var character = new GameObject("Character");
            try
            {
                Animator animator = character.AddComponent<Animator>();
                Transform hips = Child(character.transform, "Hips");
                var mask = new AvatarMask();
                Assert.That(AvatarMaskBones.Active(mask, animator, new[] { hips }), Is.EqualTo(new[] { true }));
                Object.DestroyImmediate(mask);
            }
            finally
            {
                Object.DestroyImmediate(character);
            }
        }

        private static Transform Child(Transform parent, string name)
        {
            Transform child = new GameObject(name).transform;
            child.parent = parent;
            return child;
        }
    }
}
