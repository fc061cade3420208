#nullable enable
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.BvhImport;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Editor.Humanoid;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Importers
{
    /// <summary>
    /// Turns Core's <see cref="BvhImportResult"/> into Unity objects: the skeleton prefab (a transform per
    /// joint, a stretched cube per bone), its avatar and the clip. Every number comes from Core; this only
    /// copies it across.
    /// </summary>
    internal static class BvhFigure
    {
        /// <summary>The prefab's hierarchy at the rest pose; <paramref name="joints"/> receives the joints' transforms in file order.</summary>
        public static GameObject Build(BvhImportResult import, out Transform[] joints)
        {
            var root = new GameObject(import.RootName);
            joints = new Transform[import.Joints.Count];
            for (int j = 0; j < joints.Length; j++)
            {
                ImportedJoint joint = import.Joints[j];
                Transform t = new GameObject(joint.Name).transform;
                t.parent = joint.Parent < 0 ? root.transform : joints[joint.Parent];
                t.localPosition = ToUnity(joint.RestPosition);
                t.localRotation = ToUnity(joint.RestRotation);
                joints[j] = t;
            }

            // The built-in cube mesh and the render pipeline's default material, as a primitive gets them.
            GameObject cube = GameObject.CreatePrimitive(PrimitiveType.Cube);
            Mesh mesh = cube.GetComponent<MeshFilter>().sharedMesh;
            Material material = cube.GetComponent<MeshRenderer>().sharedMaterial;
            UnityEngine.Object.DestroyImmediate(cube);
            foreach (FigureBone bone in import.Figure)
            {
                var piece = new GameObject(bone.Name);
                Transform t = piece.transform;
                t.parent = joints[bone.Joint];
                t.localPosition = ToUnity(bone.LocalPosition);
                t.localRotation = ToUnity(bone.LocalRotation);
                t.localScale = ToUnity(bone.LocalScale);
                // A mesh and a renderer only: a primitive's collider would make every bone a physics object.
                piece.AddComponent<MeshFilter>().sharedMesh = mesh;
                piece.AddComponent<MeshRenderer>().sharedMaterial = material;
            }

            return root;
        }

        /// <summary>
        /// The humanoid avatar from the file's T-pose when Core found a humanoid mapping; null when there is
        /// none or Unity refuses it (<paramref name="problem"/> then says why, for the import log).
        /// </summary>
        public static Avatar? BuildHumanoid(BvhImportResult import, GameObject root, out string? problem)
        {
            problem = null;
            HumanoidMapping? mapping = import.Humanoid;
            if (mapping == null) return null;
            var human = new HumanBone[mapping.Bones.Count];
            for (int i = 0; i < human.Length; i++)
            {
                var limit = new HumanLimit { useDefaultValues = true };
                human[i] = new HumanBone { humanName = mapping.Bones[i].Key, boneName = mapping.Bones[i].Value, limit = limit };
            }

            // The root object must be listed too: Unity finds each bone's parents by name in this list.
            var skeleton = new SkeletonBone[import.Joints.Count + 1];
            skeleton[0] = new SkeletonBone { name = import.RootName, position = new Vector3(0f, 0f, 0f), rotation = new Quaternion(0f, 0f, 0f, 1f), scale = new Vector3(1f, 1f, 1f) };
            for (int j = 0; j < import.Joints.Count; j++)
            {
                ImportedJoint joint = import.Joints[j];
                skeleton[j + 1] = new SkeletonBone { name = joint.Name, position = ToUnity(joint.RestPosition), rotation = ToUnity(joint.RestRotation), scale = new Vector3(1f, 1f, 1f) };
            }

            // Unity's model importer defaults for a humanoid rig.
            var description = new HumanDescription
            {
                human = human,
                skeleton = skeleton,
                upperArmTwist = 0.5f,
                lowerArmTwist = 0.5f,
                upperLegTwist = 0.5f,
                lowerLegTwist = 0.5f,
                armStretch = 0.05f,
                legStretch = 0.05f,
                feetSpacing = 0f,
                hasTranslationDoF = false,
            };
            Avatar avatar = AvatarBuilder.BuildHumanAvatar(root, description);
            if (avatar != null && avatar.isValid && avatar.isHuman) return avatar;
            if (avatar != null) UnityEngine.Object.DestroyImmediate(avatar);
            problem = $"{import.SourceName}: the joints map onto Unity's humanoid through the '{mapping.MapName}' names, but Unity refused the avatar built from the file's T-pose; the figure gets a generic avatar (the clip plays on it, but is not retargeted to other characters)";
            return null;
        }

        /// <summary>
        /// The clip: every joint's transform curves, and for a humanoid avatar also the body and muscle curves
        /// that Unity's humanoid reads (sampled through <see cref="HumanPoseHandler"/> on the figure), so the clip
        /// plays on this figure and on any humanoid character.
        /// </summary>
        public static AnimationClip Clip(BvhImportResult import, GameObject root, Transform[] joints, Avatar avatar, bool humanoid, BvhClipRange range)
        {
            var clip = new AnimationClip { name = range.Name, frameRate = (float)import.FrameRate };
            int[] frames = range.ClipFrames();
            IReadOnlyList<ClipCurve> curves = !range.PingPong && range.FirstFrame == 0 && range.LastFrame == import.FrameCount - 1 ? import.Curves : range.Curves(import);
            foreach (ClipCurve c in curves) clip.SetCurve(c.Path, typeof(Transform), c.Property, ToUnity(c));
            if (humanoid)
            {
                foreach (ClipCurve c in SampleHumanoidCurves(import, root, joints, avatar, frames)) clip.SetCurve(c.Path, typeof(Animator), c.Property, ToUnity(c));
            }

            if (range.Loop)
            {
                // Loop Time wraps the last frame to the first; Loop Pose spreads what is left of the seam over the clip.
                AnimationClipSettings settings = AnimationUtility.GetAnimationClipSettings(clip);
                settings.loopTime = true;
                settings.loopBlend = true;
                AnimationUtility.SetAnimationClipSettings(clip, settings);
            }

            return clip;
        }

        private static IReadOnlyList<ClipCurve> SampleHumanoidCurves(BvhImportResult import, GameObject root, Transform[] joints, Avatar avatar, int[] clipFrames)
        {
            int frames = clipFrames.Length;
            int n = joints.Length;
            var recording = new HumanPoseRecording(frames);
            var pose = new HumanPose();
            var handler = new HumanPoseHandler(avatar, root.transform);
            try
            {
                for (int k = 0; k < frames; k++)
                {
                    int f = clipFrames[k];
                    for (int j = 0; j < n; j++)
                    {
                        int r = (f * n + j) * 4;
                        joints[j].localRotation = new Quaternion(import.LocalRotations[r], import.LocalRotations[r + 1], import.LocalRotations[r + 2], import.LocalRotations[r + 3]);
                        int p = (f * n + j) * 3;
                        if (import.Joints[j].HasPositionCurves) joints[j].localPosition = new Vector3(import.LocalPositions[p], import.LocalPositions[p + 1], import.LocalPositions[p + 2]);
                    }

                    handler.GetHumanPose(ref pose);
                    recording.Record(k, pose);
                }
            }
            finally
            {
                handler.Dispose();
                // The prefab is saved after the import: leave it in its rest pose.
                for (int j = 0; j < n; j++)
                {
                    joints[j].localPosition = ToUnity(import.Joints[j].RestPosition);
                    joints[j].localRotation = ToUnity(import.Joints[j].RestRotation);
                }
            }

            return recording.Curves(1.0 / import.FrameRate);
        }

        private static AnimationCurve ToUnity(ClipCurve c)
        {
            var keys = new Keyframe[c.KeyCount];
            for (int i = 0; i < keys.Length; i++) keys[i] = new Keyframe(c.Times[i], c.Values[i], c.InTangents[i], c.OutTangents[i]);
            return new AnimationCurve(keys);
        }

        private static Vector3 ToUnity(Vector3D v) => new Vector3((float)v.X, (float)v.Y, (float)v.Z);

        // Core keeps (w, x, y, z); Unity's constructor takes (x, y, z, w).
        private static Quaternion ToUnity(QuaternionD q) => new Quaternion((float)q.X, (float)q.Y, (float)q.Z, (float)q.W);
    }
}
