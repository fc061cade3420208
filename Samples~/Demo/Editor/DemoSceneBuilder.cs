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
    /// <b>Tools → Δ-Interpolator → Build Demo Scene</b>: from this sample's two CMU takes (imported by the package's BVH importer,
    /// which cuts the <c>Idle</c>, <c>Walk</c> and <c>Jump</c> clips their <c>.meta</c> files name) builds, next to them, an
    /// Animator Controller with idle, walk and jump states, a model asset wired to the shipped default model, a settings asset
    /// with the base layer's transitions neural, and a scene with two characters side by side on that controller: one with
    /// Unity's crossfades, one with a <see cref="MotionInbetweener"/>; the <see cref="NeuralTransitionDemo"/> drives both with
    /// the same keys. Then it opens the scene: press Play. It asks before replacing a modified open scene (cancel: nothing
    /// happens), and existing files are never overwritten (new names are taken).
    /// </summary>
    internal static class DemoSceneBuilder
    {
        private const string Title = "Δ-Interpolator demo scene";
        private const string WalkFile = "cmu_09_12_walk_navigate.bvh";
        private const string TakesFile = "cmu_01_01_jumps_turn.bvh";

        // Inside the model's trained gaps (5–39 frames at 30 fps: 0.17–1.3 s), so the neural character's transitions are all neural.
        private const float WalkTransitionSeconds = 0.4f;
        private const float JumpTransitionSeconds = 0.3f;

        [MenuItem("Tools/Δ-Interpolator/Build Demo Scene")]
        private static void BuildFromMenu()
        {
            // The build opens a new scene in place of the open one: ask to save its edits first (Cancel stops here, nothing built).
            if (!EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo()) return;
            try
            {
                string scene = Build(SampleFolder());
                EditorUtility.DisplayDialog(Title, $"Built {scene}. Press Play: W walks or stops, Space jumps, R puts both back. Left: Unity's crossfade; right: neural transitions.", "OK");
            }
            catch (InvalidOperationException e)
            {
                EditorUtility.DisplayDialog(Title, e.Message, "OK");
            }
        }

        /// <summary>Builds the scene's assets in <paramref name="folder"/> (the imported sample) and opens the scene; returns its path.</summary>
        public static string Build(string folder)
        {
            string characterPath = folder + "/" + WalkFile;
            GameObject character = AssetDatabase.LoadAssetAtPath<GameObject>(characterPath);
            // Unity objects compare with ==, not ?? (a destroyed object is not a C# null).
            if (character == null) throw new InvalidOperationException($"{characterPath} is not imported as a character; the package's BVH importer makes .bvh files characters (reimport the sample)");
            AnimationClip walk = Clip(characterPath, "Walk");
            AnimationClip idle = Clip(folder + "/" + TakesFile, "Idle");
            AnimationClip jump = Clip(folder + "/" + TakesFile, "Jump");
            Avatar? avatar = null;
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(characterPath)) if (o is Avatar a) avatar = a;

            AnimatorController controller = Controller(AssetDatabase.GenerateUniqueAssetPath(folder + "/Demo Controller.controller"), idle, walk, jump);
            InbetweeningModel model = ShippedModelAssets.Create(folder + "/Demo Model.asset");
            InbetweenerSettings settings = Settings(AssetDatabase.GenerateUniqueAssetPath(folder + "/Demo Settings.asset"), model);

            Scene scene = EditorSceneManager.NewScene(NewSceneSetup.DefaultGameObjects, NewSceneMode.Single);
            // The camera looks along -Z at the characters' faces: world +X is the left of the screen.
            Animator crossfade = Character(character, avatar, controller, "Unity crossfade", 0.8f);
            Animator neural = Character(character, avatar, controller, "Neural transitions", -0.8f);
            neural.gameObject.AddComponent<MotionInbetweener>().Settings = settings;

            GameObject floor = GameObject.CreatePrimitive(PrimitiveType.Plane);
            floor.name = "Floor";
            floor.transform.localScale = new Vector3(20f, 1f, 20f);
            Camera? camera = Object.FindAnyObjectByType<Camera>();
            if (camera != null)
            {
                camera.transform.position = new Vector3(0f, 1.5f, 5f);
                camera.transform.rotation = Quaternion.Euler(8f, 180f, 0f);
            }

            var demo = new GameObject("Demo").AddComponent<NeuralTransitionDemo>();
            var d = new SerializedObject(demo);
            d.FindProperty("_crossfade").objectReferenceValue = crossfade;
            d.FindProperty("_neural").objectReferenceValue = neural;
            d.FindProperty("_camera").objectReferenceValue = camera;
            d.ApplyModifiedPropertiesWithoutUndo();

            string scenePath = AssetDatabase.GenerateUniqueAssetPath(folder + "/Demo.unity");
            if (!EditorSceneManager.SaveScene(scene, scenePath)) throw new InvalidOperationException($"could not save {scenePath}");
            return scenePath;
        }

        // Idle (default) ⇄ Walk on the bool Walk; Idle or Walk → Jump on the trigger Jump; Jump → Idle near its end. Every
        // transition has a fixed length inside the model's trained gaps, so on the neural character every one is neural.
        private static AnimatorController Controller(string path, AnimationClip idle, AnimationClip walk, AnimationClip jump)
        {
            AnimatorController controller = AnimatorController.CreateAnimatorControllerAtPath(path);
            controller.AddParameter("Walk", AnimatorControllerParameterType.Bool);
            controller.AddParameter("Jump", AnimatorControllerParameterType.Trigger);
            AnimatorStateMachine machine = controller.layers[0].stateMachine;
            AnimatorState idleState = State(machine, "Idle", idle);
            AnimatorState walkState = State(machine, "Walk", walk);
            AnimatorState jumpState = State(machine, "Jump", jump);
            machine.defaultState = idleState;
            Transition(idleState, walkState, WalkTransitionSeconds).AddCondition(AnimatorConditionMode.If, 0f, "Walk");
            Transition(walkState, idleState, WalkTransitionSeconds).AddCondition(AnimatorConditionMode.IfNot, 0f, "Walk");
            Transition(idleState, jumpState, JumpTransitionSeconds).AddCondition(AnimatorConditionMode.If, 0f, "Jump");
            Transition(walkState, jumpState, JumpTransitionSeconds).AddCondition(AnimatorConditionMode.If, 0f, "Jump");
            AnimatorStateTransition land = Transition(jumpState, idleState, WalkTransitionSeconds);
            land.hasExitTime = true;
            // The jump's last 0.4 s (of its 1.6 s) are the landing's standing frames: leave them for idle.
            land.exitTime = 1f - WalkTransitionSeconds / jump.length;
            AssetDatabase.SaveAssets();
            return controller;
        }

        private static AnimatorState State(AnimatorStateMachine machine, string name, AnimationClip clip)
        {
            AnimatorState state = machine.AddState(name);
            state.motion = clip;
            return state;
        }

        private static AnimatorStateTransition Transition(AnimatorState from, AnimatorState to, float seconds)
        {
            AnimatorStateTransition t = from.AddTransition(to);
            t.hasExitTime = false;
            t.hasFixedDuration = true;
            t.duration = seconds;
            return t;
        }

        // The shipped default model; the rig read from the figure's humanoid avatar (Automatic), or, were Unity to refuse the
        // avatar, by the CMU names and the figure's rest pose (the importer's T-pose); the base layer's transitions neural.
        private static InbetweenerSettings Settings(string path, InbetweeningModel model)
        {
            var settings = ScriptableObject.CreateInstance<InbetweenerSettings>();
            AssetDatabase.CreateAsset(settings, path);
            var s = new SerializedObject(settings);
            s.FindProperty("model").objectReferenceValue = model;
            s.FindProperty("rig").enumValueIndex = (int)CharacterRigKind.Automatic;
            s.FindProperty("jointMap").enumValueIndex = (int)BuiltInJointMap.Cmu;
            s.FindProperty("referencePose").enumValueIndex = (int)ReferencePoseSource.BindPose;
            s.ApplyModifiedPropertiesWithoutUndo();
            settings.SetNeuralTransitions(new[] { new NeuralTransitionLayer { layer = 0, enabled = true } });
            EditorUtility.SetDirty(settings);
            AssetDatabase.SaveAssets();
            return settings;
        }

        private static Animator Character(GameObject prefab, Avatar? avatar, AnimatorController controller, string name, float x)
        {
            var instance = (GameObject)PrefabUtility.InstantiatePrefab(prefab);
            instance.name = name;
            instance.transform.position = new Vector3(x, 0f, 0f);
            Animator animator = instance.GetComponent<Animator>();
            if (animator == null) animator = instance.AddComponent<Animator>();
            if (avatar != null) animator.avatar = avatar;
            animator.runtimeAnimatorController = controller;
            // The walk travels: root motion carries the character, and the camera follows.
            animator.applyRootMotion = true;
            return animator;
        }

        private static AnimationClip Clip(string bvhPath, string name)
        {
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(bvhPath)) if (o is AnimationClip c && c.name == name) return c;
            throw new InvalidOperationException($"{bvhPath} has no clip '{name}'; the sample's .bvh.meta names its clip ranges (reimport the sample with this package's BVH importer)");
        }

        // The folder this sample was imported into (Assets/Samples/<package>/<version>/Demo): where its clips are.
        private static string SampleFolder()
        {
            foreach (string guid in AssetDatabase.FindAssets(Path.GetFileNameWithoutExtension(WalkFile)))
            {
                string path = AssetDatabase.GUIDToAssetPath(guid);
                if (path.StartsWith("Assets/", StringComparison.Ordinal) && path.EndsWith("/" + WalkFile, StringComparison.Ordinal)) return path.Substring(0, path.Length - WalkFile.Length - 1);
            }

            throw new InvalidOperationException("the Demo sample is not imported; Window → Package Manager → Delta Interpolator Motion In-betweening → Samples → Demo → Import");
        }
    }
}
