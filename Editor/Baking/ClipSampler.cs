#nullable enable
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Skeletons;
using UnityEditor;
using DeltaInterpolator.Editor.Humanoid;
using DeltaInterpolator.Unity;
using UnityEngine;

namespace DeltaInterpolator.Editor.Baking
{
    /// <summary>
    /// The Unity side of a bake's input and output: a clip's pose-curve key times (transform curves or a humanoid
    /// clip's body and muscle curves, for <see cref="ClipKeyReader"/>), the character's rig bones sampled through
    /// <see cref="AnimationMode"/> into a <see cref="CharacterPoseTrack"/>, and baked motion turned into a humanoid
    /// clip's curves through <see cref="HumanPoseHandler"/>. Every conversion is Core's.
    /// </summary>
    internal static class ClipSampler
    {
        private static HashSet<string>? s_muscleProperties;

        /// <summary>Every muscle's curve property as humanoid clips name them.</summary>
        public static HashSet<string> MuscleProperties()
        {
            if (s_muscleProperties == null)
            {
                var set = new HashSet<string>(StringComparer.Ordinal);
                foreach (string muscle in HumanTrait.MuscleName) set.Add(HumanoidCurves.MuscleProperty(muscle));
                s_muscleProperties = set;
            }

            return s_muscleProperties;
        }

        /// <summary>The key times of every pose curve of <paramref name="clip"/>: transform rotations and positions, or a humanoid clip's body and muscles.</summary>
        public static List<IReadOnlyList<float>> PoseKeyTimes(AnimationClip clip)
        {
            HashSet<string> muscles = MuscleProperties();
            var result = new List<IReadOnlyList<float>>();
            foreach (EditorCurveBinding binding in AnimationUtility.GetCurveBindings(clip))
            {
                if (!ClipKeyReader.IsPoseProperty(binding.propertyName) && !HumanoidCurves.IsPoseProperty(binding.propertyName, muscles)) continue;
                AnimationCurve curve = AnimationUtility.GetEditorCurve(clip, binding);
                if (curve == null) continue;
                Keyframe[] keys = curve.keys;
                var times = new float[keys.Length];
                for (int i = 0; i < keys.Length; i++) times[i] = keys[i].time;
                result.Add(times);
            }

            return result;
        }

        /// <summary>Each bone's path under <paramref name="root"/>, as curve bindings write them.</summary>
        public static string[] Paths(Transform root, Transform[] bones)
        {
            var paths = new string[bones.Length];
            for (int b = 0; b < bones.Length; b++) paths[b] = AnimationUtility.CalculateTransformPath(bones[b], root);
            return paths;
        }

        /// <summary>
        /// Samples <paramref name="clip"/> on <paramref name="character"/> at each time (through the Animator's avatar
        /// for a humanoid clip) and writes the rig bones' transforms into frame <c>frames[i]</c> of <paramref name="track"/>.
        /// Call inside an <see cref="AnimationModeScope"/>: the scene is restored when it ends.
        /// </summary>
        /// <param name="track">The character's track.</param>
        /// <param name="character">The Animator's GameObject (its curve paths start here).</param>
        /// <param name="bones">The rig's bones, in <see cref="CharacterRig.BoneNames"/> order.</param>
        /// <param name="clip">The clip to sample.</param>
        /// <param name="frames">Frame index in the track of each sample.</param>
        /// <param name="times">Clip time (seconds) of each sample.</param>
        public static void SampleInto(CharacterPoseTrack track, GameObject character, Transform[] bones, AnimationClip clip, IReadOnlyList<int> frames, IReadOnlyList<double> times)
        {
            var root = new double[3];
            var rotations = new double[4 * bones.Length];
            for (int i = 0; i < frames.Count; i++)
            {
                AnimationMode.BeginSampling();
                AnimationMode.SampleAnimationClip(character, clip, (float)times[i]);
                AnimationMode.EndSampling();
                UnityPoses.Read(bones, 0, root, rotations);
                track.SetUnityPose(frames[i], root, rotations);
            }
        }

        /// <summary>
        /// The curves of a humanoid clip (body and muscles, on the Animator) that play <paramref name="motion"/>: each
        /// frame is put on the bones and read back as a human pose. The bones are put back before returning.
        /// </summary>
        /// <param name="animator">The character's humanoid Animator.</param>
        /// <param name="rig">The character's rig.</param>
        /// <param name="bones">The rig's bones, in <see cref="CharacterRig.BoneNames"/> order.</param>
        /// <param name="motion">Motion on <see cref="CharacterRig.Skeleton"/> (a bake's <c>OnRig</c>).</param>
        public static IReadOnlyList<ClipCurve> HumanoidClipCurves(Animator animator, CharacterRig rig, Transform[] bones, MotionClip motion)
        {
            int frames = motion.FrameCount;
            var recording = new HumanPoseRecording(frames);
            var savedPositions = new Vector3[bones.Length];
            var savedRotations = new Quaternion[bones.Length];
            for (int b = 0; b < bones.Length; b++)
            {
                savedPositions[b] = bones[b].localPosition;
                savedRotations[b] = bones[b].localRotation;
            }

            var root = new double[3];
            var rotations = new double[4 * bones.Length];
            var pose = new HumanPose();
            var handler = new HumanPoseHandler(animator.avatar, animator.transform);
            try
            {
                for (int f = 0; f < frames; f++)
                {
                    CharacterPoseTrack.ReadUnityPose(rig, motion, f, root, rotations);
                    UnityPoses.Apply(bones, 0, root, rotations);
                    handler.GetHumanPose(ref pose);
                    recording.Record(f, pose);
                }
            }
            finally
            {
                handler.Dispose();
                for (int b = 0; b < bones.Length; b++)
                {
                    bones[b].localPosition = savedPositions[b];
                    bones[b].localRotation = savedRotations[b];
                }
            }

            return recording.Curves(motion.FrameTime);
        }
    }

    /// <summary>
    /// Editor animation mode for the length of a bake: what sampling writes onto the scene is previewed, never
    /// saved, and goes back when the scope ends. Refuses to start inside another animation mode (the Animation
    /// window's preview or record), whose changes ending it would throw away.
    /// </summary>
    internal sealed class AnimationModeScope : IDisposable
    {
        /// <exception cref="InvalidOperationException">The editor is already in animation mode.</exception>
        public AnimationModeScope()
        {
            if (AnimationMode.InAnimationMode())
            {
                throw new InvalidOperationException("the editor is in animation mode (the Animation window previews or records); leave preview and record mode, then bake");
            }

            AnimationMode.StartAnimationMode();
        }

        public void Dispose() => AnimationMode.StopAnimationMode();
    }
}
