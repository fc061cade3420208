using System;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Which of a character's driven bones an <c>AvatarMask</c> lets a controller layer drive: a humanoid avatar's bones by
    /// the mask's body parts (<c>GetHumanoidBodyPartActive</c>), a generic rig's by the mask's transform paths
    /// (<c>GetTransformPath</c>/<c>GetTransformActive</c>, relative to the Animator; a mask without transforms lets every
    /// bone through, as the Animator treats it). Players cannot read the masks inside a controller, so the settings give the mask.
    /// </summary>
    internal static class AvatarMaskBones
    {
        /// <summary>One flag per bone of <paramref name="bones"/>: true where <paramref name="mask"/> lets its layer drive the bone.</summary>
        public static bool[] Active(AvatarMask mask, Animator animator, Transform[] bones)
        {
            if (mask == null) throw new ArgumentNullException(nameof(mask));
            var active = new bool[bones.Length];
            if (animator.isHuman)
            {
                for (int id = 0; id < (int)HumanBodyBones.LastBone; id++)
                {
                    Transform bone = animator.GetBoneTransform((HumanBodyBones)id);
                    int index = bone == null ? -1 : Array.IndexOf(bones, bone);
                    if (index >= 0) active[index] = mask.GetHumanoidBodyPartActive(BodyPart((HumanBodyBones)id));
                }

                return active;
            }

            int paths = mask.transformCount;
            for (int b = 0; b < bones.Length; b++)
            {
                if (paths == 0)
                {
                    active[b] = true;
                    continue;
                }

                string path = PathOf(bones[b], animator.transform);
                for (int p = 0; p < paths; p++)
                {
                    if (mask.GetTransformPath(p) != path) continue;
                    active[b] = mask.GetTransformActive(p);
                    break;
                }
            }

            return active;
        }

        /// <summary>The mask body part a humanoid bone belongs to (the grouping of Unity's Avatar Mask inspector).</summary>
        public static AvatarMaskBodyPart BodyPart(HumanBodyBones bone)
        {
            switch (bone)
            {
                case HumanBodyBones.Hips:
                case HumanBodyBones.Spine:
                case HumanBodyBones.Chest:
                case HumanBodyBones.UpperChest:
                    return AvatarMaskBodyPart.Body;
                case HumanBodyBones.Neck:
                case HumanBodyBones.Head:
                case HumanBodyBones.LeftEye:
                case HumanBodyBones.RightEye:
                case HumanBodyBones.Jaw:
                    return AvatarMaskBodyPart.Head;
                case HumanBodyBones.LeftUpperLeg:
                case HumanBodyBones.LeftLowerLeg:
                case HumanBodyBones.LeftFoot:
                case HumanBodyBones.LeftToes:
                    return AvatarMaskBodyPart.LeftLeg;
                case HumanBodyBones.RightUpperLeg:
                case HumanBodyBones.RightLowerLeg:
                case HumanBodyBones.RightFoot:
                case HumanBodyBones.RightToes:
                    return AvatarMaskBodyPart.RightLeg;
                case HumanBodyBones.LeftShoulder:
                case HumanBodyBones.LeftUpperArm:
                case HumanBodyBones.LeftLowerArm:
                case HumanBodyBones.LeftHand:
                    return AvatarMaskBodyPart.LeftArm;
                case HumanBodyBones.RightShoulder:
                case HumanBodyBones.RightUpperArm:
                case HumanBodyBones.RightLowerArm:
                case HumanBodyBones.RightHand:
                    return AvatarMaskBodyPart.RightArm;
                default:
                    // The fingers follow the enum's order: the left hand's 15 bones, then the right hand's.
                    return bone <= HumanBodyBones.LeftLittleDistal ? AvatarMaskBodyPart.LeftFingers : AvatarMaskBodyPart.RightFingers;
            }
        }

        // The path an AvatarMask stores for a transform: names from below the Animator down to it, joined by '/'.
        private static string PathOf(Transform bone, Transform root)
        {
            string path = bone.name;
            for (Transform? t = bone.parent; t != null && t != root; t = t.parent) path = t.name + "/" + path;
            return path;
        }
    }
}
