#nullable enable
using System;
using System.IO;
using DeltaInterpolator.Editor.Models;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEditor.Animations;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Samples.Demo.Editor
{
    /// <summary>
    /// <b>Tools → Δ-Interpolator → Build Demo Scene</b>: from this sample's two CMU clips (imported as characters and
    /// clips by the package's BVH importer) builds, next to them, a scene with the character playing the jumps
    /// clip through an Animator Controller, a <see cref="MotionInbetweener"/> with a settings asset and the shipped
    /// default model, and the <see cref="NeuralTransitionDemo"/> controls (an on-screen button and Space), then opens
    /// it: press Play. Existing files are never overwritten (new names are taken).
    /// </summary>
    internal static class DemoSceneBuilder
    {
        private const string Title = "Δ-Interpolator demo scene";
        private const string CharacterFile = "cmu_09_12_walk_navigate.bvh"; // its frame 0 is a T-pose: the reference pose
        private const string IdleFile = "cmu_01_01_jumps_turn.bvh";

        [MenuItem("Tools/Δ-Interpolator/Build Demo Scene")]
        private static void BuildFromMenu()
        {
            try
            {
                string scene = Build(SampleFolder());
                EditorUtility.DisplayDialog(Title, $"Built {scene}. Press Play, then the button or Space.", "OK");
            }
            catch (InvalidOperationException e)
            {
                EditorUtility.DisplayDialog(Title, e.Message, "OK");
            }
        }

        /// <summary>Builds the scene's assets in <paramref name="folder"/> (the imported sample) and opens the scene; returns its path.</summary>
        public static string Build(string folder)
        {
            string characterPath = folder + "/" + CharacterFile;
            GameObject character = AssetDatabase.LoadAssetAtPath<GameObject>(characterPath);
            // Unity objects compare with ==, not ?? (a destroyed object is not a C# null).
            if (character == null) throw new InvalidOperationException($"{characterPath} is not imported as a character; the package's BVH importer makes .bvh files characters (reimport the sample)");
            AnimationClip walk = Clip(characterPath);
            AnimationClip jumps = Clip(folder + "/" + IdleFile);
            Avatar? avatar = null;
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(characterPath)) if (o is Avatar a) avatar = a;

            AnimatorController controller = AnimatorController.CreateAnimatorControllerAtPathWithClip(AssetDatabase.GenerateUniqueAssetPath(folder + "/Demo Controller.controller"), jumps);
            InbetweeningModel model = ShippedModelAssets.Create(folder + "/Demo Model.asset");
            var settings = ScriptableObject.CreateInstance<InbetweenerSettings>();
            AssetDatabase.CreateAsset(settings, AssetDatabase.GenerateUniqueAssetPath(folder + "/Demo Settings.asset"));
            var s = new SerializedObject(settings);
            s.FindProperty("model").objectReferenceValue = model;
            bool humanoid = avatar != null && avatar.isHuman;
            // A humanoid avatar brings its own T-pose; otherwise the CMU names and the walk clip's first frame (a T-pose).
            s.FindProperty("rig").enumValueIndex = (int)(humanoid ? CharacterRigKind.Humanoid : CharacterRigKind.Generic);
            s.FindProperty("jointMap").enumValueIndex = (int)BuiltInJointMap.Cmu;
            s.FindProperty("referencePose").enumValueIndex = (int)ReferencePoseSource.ClipFrame;
            s.FindProperty("referenceClip").objectReferenceValue = walk;
            s.FindProperty("referenceClipTime").floatValue = 0f;
            s.ApplyModifiedPropertiesWithoutUndo();
            AssetDatabase.SaveAssets();

            Scene scene = EditorSceneManager.NewScene(NewSceneSetup.DefaultGameObjects, NewSceneMode.Single);
            var instance = (GameObject)PrefabUtility.InstantiatePrefab(character);
            instance.name = "Character";
            Animator animator = instance.GetComponent<Animator>();
            if (animator == null) animator = instance.AddComponent<Animator>();
            if (avatar != null) animator.avatar = avatar;
            animator.runtimeAnimatorController = controller;
            animator.applyRootMotion = false;
            var inbetweener = instance.AddComponent<MotionInbetweener>();
            inbetweener.Settings = settings;
            var demo = instance.AddComponent<NeuralTransitionDemo>();
            var d = new SerializedObject(demo);
            d.FindProperty("_target").objectReferenceValue = walk;
            d.ApplyModifiedPropertiesWithoutUndo();

            GameObject floor = GameObject.CreatePrimitive(PrimitiveType.Plane);
            floor.name = "Floor";
            floor.transform.localScale = new Vector3(4f, 1f, 4f);
            Camera? camera = Object.FindAnyObjectByType<Camera>();
            if (camera != null)
            {
                camera.transform.position = new Vector3(0f, 1.4f, 4.5f);
                camera.transform.rotation = Quaternion.Euler(8f, 180f, 0f);
            }

            string scenePath = AssetDatabase.GenerateUniqueAssetPath(folder + "/Demo.unity");
            if (!EditorSceneManager.SaveScene(scene, scenePath)) throw new InvalidOperationException($"could not save {scenePath}");
            return scenePath;
        }

        private static AnimationClip Clip(string bvhPath)
        {
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(bvhPath)) if (o is AnimationClip c) return c;
            throw new InvalidOperationException($"{bvhPath} has no clip; the package's BVH importer makes one (reimport the sample)");
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
