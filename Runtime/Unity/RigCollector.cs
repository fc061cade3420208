using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using UnityEngine;
using CoreJointMap = DeltaInterpolator.Core.Retargeting.JointMap;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Gathers what Core's <see cref="CharacterRig"/> needs from the scene: the transforms under the Animator
    /// (names, parents), which of them play a part (the avatar's <c>HumanBodyBones</c>, or the joint map's
    /// names), their local positions and reference rotations (the avatar's T-pose, the bind pose, or a clip
    /// frame), and the armature above the root bone. Every decision (which bones, how they map, whether the
    /// reference is a T-pose) is Core's.
    /// </summary>
    internal static class RigCollector
    {
        /// <summary>The character's rig, the joint map to use on it, and the bones in rig order.</summary>
        public static CharacterRig Collect(Animator animator, InbetweenerSettings settings, Skeleton model, out CoreJointMap jointMap, out Transform[] bones)
        {
            string character = animator.name;
            var all = new List<Transform>();
            var names = new List<string>();
            var parents = new List<int>();
            Walk(animator.transform, -1, all, names, parents);
            string?[] roles;
            int root;
            CharacterRigKind kind = settings.RigOf(animator);
            if (kind == CharacterRigKind.Humanoid)
            {
                if (!animator.isHuman)
                {
                    throw new InvalidOperationException($"the settings {settings.name} ask for a humanoid avatar but the Animator has {(animator.avatar == null ? "no avatar" : "a generic avatar")}; set the model's Animation Type to Humanoid, or choose the Generic rig with a joint map");
                }

                jointMap = CoreJointMap.UnityHumanoid;
                roles = new string?[all.Count];
                root = -1;
                foreach (string joint in jointMap.TargetJoints)
                {
                    foreach (string part in jointMap.SourceChain(joint)!)
                    {
                        var id = (HumanBodyBones)Enum.Parse(typeof(HumanBodyBones), part);
                        Transform bone = animator.GetBoneTransform(id);
                        int index = bone == null ? -1 : all.IndexOf(bone);
                        if (index < 0) continue;
                        roles[index] = part;
                        if (id == HumanBodyBones.Hips) root = index;
                    }
                }
            }
            else
            {
                jointMap = GenericJointMap(settings);
                roles = RigBoneSelection.RolesFromJointMap(names, jointMap, model.Names[0], character, out root);
            }

            RigBoneSelection selection = RigBoneSelection.Select(names, parents, roles, root, model.Names[0], character);
            int n = selection.Transforms.Count;
            bones = new Transform[n];
            for (int b = 0; b < n; b++) bones[b] = all[selection.Transforms[b]];

            RequireUniformScale(animator.transform, character);
            Transform? armature = bones[0].parent;
            RootFrame armatureFrame = RootFrame.Identity;
            if (armature != null && armature != animator.transform)
            {
                RequireUniformScale(armature, character);
                armatureFrame = WorldFrame(animator.transform).Inverse().Then(WorldFrame(armature));
            }

            var positions = new double[3 * n];
            var rotations = new double[4 * n];
            if (kind == CharacterRigKind.Humanoid)
            {
                AvatarTPose(animator, bones, positions, rotations, character);
            }
            else if (settings.ReferencePose == ReferencePoseSource.ClipFrame)
            {
                AnimationClip clip = settings.ReferenceClip != null ? settings.ReferenceClip : throw new InvalidOperationException($"the settings {settings.name} take the reference pose from a clip frame but name no clip; assign the Reference Clip (a clip showing a T-pose)");
                ClipFramePose(animator, clip, settings.ReferenceClipTime, bones, positions, rotations);
            }
            else
            {
                for (int b = 0; b < n; b++) Write(bones[b].localPosition, bones[b].localRotation, positions, rotations, b);
            }

            var rig = new CharacterRig(character, selection.BoneNames, selection.Parents, positions, rotations, armatureFrame);
            return kind == CharacterRigKind.Generic && settings.ReferencePose == ReferencePoseSource.ModelAxes ? rig.WithModelTPoseByAxes() : rig;
        }

        /// <summary>Where <paramref name="t"/> stands in the world (its x scale stands for its uniform scale).</summary>
        public static RootFrame WorldFrame(Transform t)
        {
            Vector3 p = t.position;
            Quaternion q = t.rotation;
            return new RootFrame(new Vector3D(p.x, p.y, p.z), new QuaternionD(q.w, q.x, q.y, q.z), t.lossyScale.x);
        }

        private static CoreJointMap GenericJointMap(InbetweenerSettings settings)
        {
            CoreJointMap builtIn = settings.JointMap switch
            {
                BuiltInJointMap.Cmu => CoreJointMap.Cmu,
                BuiltInJointMap.Mixamo => CoreJointMap.Mixamo,
                BuiltInJointMap.Poser => CoreJointMap.Poser,
                _ => CoreJointMap.Lafan1,
            };
            TextAsset? json = settings.JointMapJson;
            CoreJointMap map = json != null ? CoreJointMap.FromJson(json.text, json.name, builtIn) : builtIn;
            var renamed = new List<KeyValuePair<string, string>>();
            foreach (JointBinding binding in settings.Joints) renamed.Add(new KeyValuePair<string, string>(binding.joint, binding.bone));
            return map.WithBones(renamed);
        }

        private static void Walk(Transform parent, int parentIndex, List<Transform> all, List<string> names, List<int> parents)
        {
            for (int c = 0; c < parent.childCount; c++)
            {
                Transform child = parent.GetChild(c);
                int index = all.Count;
                all.Add(child);
                names.Add(child.name);
                parents.Add(parentIndex);
                Walk(child, index, all, names, parents);
            }
        }

        // The avatar's own T-pose: the skeleton the humanoid avatar was configured with, by transform name.
        private static void AvatarTPose(Animator animator, Transform[] bones, double[] positions, double[] rotations, string character)
        {
            SkeletonBone[] skeleton = animator.avatar.humanDescription.skeleton ?? new SkeletonBone[0];
            var byName = new Dictionary<string, SkeletonBone>(StringComparer.Ordinal);
            foreach (SkeletonBone bone in skeleton)
            {
                if (bone.name != null && !byName.ContainsKey(bone.name)) byName.Add(bone.name, bone);
            }

            var missing = new List<string>();
            for (int b = 0; b < bones.Length; b++)
            {
                if (byName.TryGetValue(bones[b].name, out SkeletonBone pose)) Write(pose.position, pose.rotation, positions, rotations, b);
                else missing.Add(bones[b].name);
            }

            if (missing.Count > 0)
            {
                throw new InvalidOperationException($"{character}: the avatar's T-pose (humanDescription.skeleton) has no bone called {string.Join(", ", missing)}; expected an avatar created from this hierarchy (re-import the model with Animation Type Humanoid)");
            }
        }

        // The reference pose a clip shows at a time, read off the scene: sampled onto a hidden, renderer-free copy of the
        // character's hierarchy (transforms only, at the character's local poses, with its avatar), never onto the character,
        // so nothing that watches its bones (physics, constraints, other scripts, the Editor's dirty state) sees them move.
        private static void ClipFramePose(Animator animator, AnimationClip clip, float time, Transform[] bones, double[] positions, double[] rotations)
        {
            var copy = new GameObject(animator.name + " (Δ-Interpolator reference pose)") { hideFlags = HideFlags.HideAndDontSave };
            try
            {
                var copies = new Dictionary<Transform, Transform>();
                CopyHierarchy(animator.transform, copy.transform, copies);
                copy.AddComponent<Animator>().avatar = animator.avatar;
                clip.SampleAnimation(copy, time);
                for (int b = 0; b < bones.Length; b++)
                {
                    Transform t = copies[bones[b]];
                    Write(t.localPosition, t.localRotation, positions, rotations, b);
                }
            }
            finally
            {
                UnityEngine.Object.DestroyImmediate(copy);
            }
        }

        private static void CopyHierarchy(Transform source, Transform copy, Dictionary<Transform, Transform> copies)
        {
            for (int c = 0; c < source.childCount; c++)
            {
                Transform child = source.GetChild(c);
                Transform childCopy = new GameObject(child.name) { hideFlags = HideFlags.HideAndDontSave }.transform;
                childCopy.parent = copy;
                childCopy.localPosition = child.localPosition;
                childCopy.localRotation = child.localRotation;
                childCopy.localScale = child.localScale;
                copies.Add(child, childCopy);
                CopyHierarchy(child, childCopy, copies);
            }
        }

        private static void RequireUniformScale(Transform t, string character)
        {
            Vector3 s = t.lossyScale;
            double tolerance = 1e-3 * Math.Abs(s.x);
            if (!(s.x > 0) || Math.Abs(s.y - s.x) > tolerance || Math.Abs(s.z - s.x) > tolerance)
            {
                throw new InvalidOperationException($"{character}: '{t.name}' has the scale ({s.x}, {s.y}, {s.z}) in the world; expected a uniform positive scale on the character and the armature above its hips (bones keep their directions only under a uniform scale)");
            }
        }

        private static void Write(Vector3 position, Quaternion rotation, double[] positions, double[] rotations, int bone)
        {
            positions[3 * bone] = position.x;
            positions[3 * bone + 1] = position.y;
            positions[3 * bone + 2] = position.z;
            rotations[4 * bone] = rotation.w;
            rotations[4 * bone + 1] = rotation.x;
            rotations[4 * bone + 2] = rotation.y;
            rotations[4 * bone + 3] = rotation.z;
        }
    }
}
