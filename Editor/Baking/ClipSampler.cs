#nullable enable
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Baking
{
    /// <summary>
    /// The Unity side of reading keys: a clip's pose-curve key times (for <see cref="ClipKeyReader"/>) and
    /// the character's pose sampled at given times (into a <see cref="KeyPoseTrack"/>). Sampling moves the
    /// character's bones; <see cref="SampleInto"/> puts them back before returning.
    /// </summary>
    internal static class ClipSampler
    {
        /// <summary>The key times of every rotation and position curve of <paramref name="clip"/>.</summary>
        public static List<IReadOnlyList<float>> PoseKeyTimes(AnimationClip clip)
        {
            var result = new List<IReadOnlyList<float>>();
            foreach (EditorCurveBinding binding in AnimationUtility.GetCurveBindings(clip))
            {
                if (!ClipKeyReader.IsPoseProperty(binding.propertyName)) continue;
                AnimationCurve curve = AnimationUtility.GetEditorCurve(clip, binding);
                if (curve == null) continue;
                Keyframe[] keys = curve.keys;
                var times = new float[keys.Length];
                for (int i = 0; i < keys.Length; i++) times[i] = keys[i].time;
                result.Add(times);
            }

            return result;
        }

        /// <summary>Every transform's path under <paramref name="root"/> ("" for the root), as curve bindings write them.</summary>
        public static List<string> TransformPaths(Transform root)
        {
            var paths = new List<string>();
            foreach (Transform t in root.GetComponentsInChildren<Transform>(true))
            {
                paths.Add(AnimationUtility.CalculateTransformPath(t, root));
            }

            return paths;
        }

        /// <summary>
        /// Samples <paramref name="clip"/> on <paramref name="character"/> at each time and writes the
        /// bones' local rotations and the root bone's local position into frame <c>frames[i]</c> of
        /// <paramref name="track"/>.
        /// </summary>
        /// <param name="track">The model-space track to fill.</param>
        /// <param name="character">The GameObject the clip animates (its curve paths start here).</param>
        /// <param name="bones">The model's joints' transforms, in joint order (joint 0 is the root bone).</param>
        /// <param name="clip">The clip to sample (a generic clip; humanoid clips need an Animator and are not supported here).</param>
        /// <param name="frames">Frame index in the track of each sample.</param>
        /// <param name="times">Clip time (seconds) of each sample.</param>
        public static void SampleInto(KeyPoseTrack track, GameObject character, Transform[] bones, AnimationClip clip, IReadOnlyList<int> frames, IReadOnlyList<double> times)
        {
            var savedRotations = new Quaternion[bones.Length];
            var savedPositions = new Vector3[bones.Length];
            for (int j = 0; j < bones.Length; j++)
            {
                savedRotations[j] = bones[j].localRotation;
                savedPositions[j] = bones[j].localPosition;
            }

            var pose = new float[bones.Length * 4];
            try
            {
                for (int i = 0; i < frames.Count; i++)
                {
                    clip.SampleAnimation(character, (float)times[i]);
                    for (int j = 0; j < bones.Length; j++)
                    {
                        Quaternion q = bones[j].localRotation;
                        pose[4 * j] = q.x;
                        pose[4 * j + 1] = q.y;
                        pose[4 * j + 2] = q.z;
                        pose[4 * j + 3] = q.w;
                    }

                    Vector3 root = bones[0].localPosition;
                    track.SetUnityPose(frames[i], pose, root.x, root.y, root.z);
                }
            }
            finally
            {
                // Sampling is a read: leave the scene as it was.
                for (int j = 0; j < bones.Length; j++)
                {
                    bones[j].localRotation = savedRotations[j];
                    bones[j].localPosition = savedPositions[j];
                }
            }
        }
    }
}
