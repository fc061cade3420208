#nullable enable
using System;
using System.IO;
using DeltaInterpolator.Editor.Models;
using DeltaInterpolator.Timeline;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.Playables;
using UnityEngine.SceneManagement;
using UnityEngine.Timeline;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Samples.Demo.Timeline.Editor
{
    /// <summary>
    /// <b>Tools → Δ-Interpolator → Build Timeline Demo</b> (with com.unity.timeline installed): from this sample's two CMU
    /// clips builds a scene with two copies of the character side by side and one Timeline: on the left a Neural
    /// Animation Track plays Walk, a 0.3 s blend, Jump, a 0.6 s gap and Walk again; on the right an
    /// Animation Track plays the same clips at the same times with Timeline's crossfade (and nothing in the gap). Open
    /// the Timeline window and scrub: the left character shows the model's in-betweens. Existing files are never
    /// overwritten (new names are taken).
    /// </summary>
    internal static class BuildTimelineDemo
    {
        private const string Title = "Δ-Interpolator Timeline demo";
        private const string CharacterFile = "cmu_09_12_walk_navigate.bvh"; // its frame 0 is a T-pose: the reference pose
        private const string JumpsFile = "cmu_01_01_jumps_turn.bvh";

        [MenuItem("Tools/Δ-Interpolator/Build Timeline Demo")]
        private static void BuildFromMenu()
        {
            try
            {
                string scene = Build(SampleFolder());
                EditorUtility.DisplayDialog(Title, $"Built {scene}. Select Director, open Window → Sequencing → Timeline and scrub, or press Play.", "OK");
            }
            catch (InvalidOperationException e)
            {
                EditorUtility.DisplayDialog(Title, e.Message, "OK");
            }
        }

        /// <summary>Builds the Timeline demo's assets in <paramref name="folder"/> (the imported sample) and opens its scene; returns its path.</summary>
        public static string Build(string folder)
        {
            string characterPath = folder + "/" + CharacterFile;
            GameObject character = AssetDatabase.LoadAssetAtPath<GameObject>(characterPath);
            if (character == null) throw new InvalidOperationException($"{characterPath} is not imported as a character; the package's BVH importer makes .bvh files characters (reimport the sample)");
            AnimationClip walk = Clip(characterPath, "Walk");
            AnimationClip jumps = Clip(folder + "/" + JumpsFile, "Jump");
            Avatar? avatar = null;
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(characterPath)) if (o is Avatar a) avatar = a;
            bool humanoid = avatar != null && avatar.isHuman;

            InbetweenerSettings settings = Settings(folder, walk, humanoid);
            var timeline = ScriptableObject.CreateInstance<TimelineAsset>();
            AssetDatabase.CreateAsset(timeline, AssetDatabase.GenerateUniqueAssetPath(folder + "/Timeline Demo.playable"));

            // Within each clip's own length (the sample's Walk is one 1.11 s gait cycle, Jump 1.6 s): Walk 0–1.1 s, Jump from
            // 0.8 s (a 0.3 s blend, 8 missing frames at 30 fps) to 2.4 s, then after a 0.6 s gap (17 missing frames) Walk from 3 s.
            var neural = timeline.CreateTrack<NeuralAnimationTrack>(null!, "Neural blends");
            neural.Settings = settings;
            var crossfade = timeline.CreateTrack<AnimationTrack>(null!, "Timeline crossfade");
            Place(neural.CreateClip<AnimationPlayableAsset>(), crossfade.CreateClip(walk), walk, 0.0, 1.1, 0.0);
            Place(neural.CreateClip<AnimationPlayableAsset>(), crossfade.CreateClip(jumps), jumps, 0.8, 1.6, 0.0);
            Place(neural.CreateClip<AnimationPlayableAsset>(), crossfade.CreateClip(walk), walk, 3.0, 1.1, 0.0);
            AssetDatabase.SaveAssets();

            Scene scene = EditorSceneManager.NewScene(NewSceneSetup.DefaultGameObjects, NewSceneMode.Single);
            Animator left = Character(character, avatar, "Neural blends", new Vector3(-1f, 0f, 0f));
            Animator right = Character(character, avatar, "Timeline crossfade", new Vector3(1f, 0f, 0f));
            var director = new GameObject("Director").AddComponent<PlayableDirector>();
            director.playableAsset = timeline;
            director.SetGenericBinding(neural, left);
            director.SetGenericBinding(crossfade, right);

            Camera? camera = Object.FindAnyObjectByType<Camera>();
            if (camera != null)
            {
                camera.transform.position = new Vector3(0f, 1.4f, 5.5f);
                camera.transform.rotation = Quaternion.Euler(8f, 180f, 0f);
            }

            string scenePath = AssetDatabase.GenerateUniqueAssetPath(folder + "/Timeline Demo.unity");
            if (!EditorSceneManager.SaveScene(scene, scenePath)) throw new InvalidOperationException($"could not save {scenePath}");
            return scenePath;
        }

        /// <summary>The same clip at the same time on both tracks: <paramref name="clipIn"/> seconds into <paramref name="animation"/>.</summary>
        private static void Place(TimelineClip onNeural, TimelineClip onCrossfade, AnimationClip animation, double start, double duration, double clipIn)
        {
            ((AnimationPlayableAsset)onNeural.asset).clip = animation;
            foreach (TimelineClip clip in new[] { onNeural, onCrossfade })
            {
                clip.start = start;
                clip.duration = duration;
                clip.clipIn = clipIn;
                clip.displayName = animation.name;
            }
        }

        private static Animator Character(GameObject character, Avatar? avatar, string name, Vector3 position)
        {
            var instance = (GameObject)PrefabUtility.InstantiatePrefab(character);
            instance.name = name;
            instance.transform.position = position;
            Animator animator = instance.GetComponent<Animator>();
            if (animator == null) animator = instance.AddComponent<Animator>();
            if (avatar != null) animator.avatar = avatar;
            animator.applyRootMotion = false;
            return animator;
        }

        /// <summary>The model and the character's rig, as the Demo scene's settings give them (the CMU names, the walk's T-pose frame).</summary>
        private static InbetweenerSettings Settings(string folder, AnimationClip walk, bool humanoid)
        {
            InbetweeningModel model = ShippedModelAssets.Create(folder + "/Timeline Demo Model.asset");
            var settings = ScriptableObject.CreateInstance<InbetweenerSettings>();
            AssetDatabase.CreateAsset(settings, AssetDatabase.GenerateUniqueAssetPath(folder + "/Timeline Demo Settings.asset"));
            var s = new SerializedObject(settings);
            s.FindProperty("model").objectReferenceValue = model;
            s.FindProperty("rig").enumValueIndex = (int)(humanoid ? CharacterRigKind.Humanoid : CharacterRigKind.Generic);
            s.FindProperty("jointMap").enumValueIndex = (int)BuiltInJointMap.Cmu;
            s.FindProperty("referencePose").enumValueIndex = (int)ReferencePoseSource.ClipFrame;
            s.FindProperty("referenceClip").objectReferenceValue = walk;
            s.FindProperty("referenceClipTime").floatValue = 0f;
            s.ApplyModifiedPropertiesWithoutUndo();
            return settings;
        }

        /// <summary>The clip called <paramref name="name"/> that the BVH importer cut from the take (its .bvh.meta names it).</summary>
        private static AnimationClip Clip(string bvhPath, string name)
        {
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(bvhPath)) if (o is AnimationClip c && c.name == name) return c;
            throw new InvalidOperationException($"{bvhPath} has no clip '{name}'; the package's BVH importer cuts it as the sample's .bvh.meta says (reimport the sample)");
        }

        // The folder this sample was imported into (Assets/Samples/<package>/<version>/Demo): where its clips are.
        private static string SampleFolder()
        {
            foreach (string guid in AssetDatabase.FindAssets(Path.GetFileNameWithoutExtension(CharacterFile)))
            {
                string path = AssetDatabase.GUIDToAssetPath(guid);
                if (path.StartsWith("Assets/", StringComparison.Ordinal) && path.EndsWith("/" + CharacterFile, StringComparison.Ordinal)) return path.Substring(0, path.Length - CharacterFile.Length - 1);
            }

            throw new InvalidOperationException("the Demo sample is not imported; Window → Package Manager → Delta Interpolator Motion In-betweening → Samples → Demo → Import");
        }
    }
}
