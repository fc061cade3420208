#if UNITY_EDITOR
#nullable enable
using System;
using System.Collections;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Editor.Models;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.Animations;
using UnityEngine;
using UnityEngine.TestTools;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Tests.PlayMode
{
    /// <summary>
    /// What the engine does with the package, checked in the real engine (Test Runner → PlayMode; steps in
    /// <c>Documentation~/unity-verification.md</c>): the package's BVH importer turns a Demo sample clip into a humanoid
    /// figure, which walks with root motion on, turned 90° from the world's +Z, and is sent to a later frame of its clip.
    /// It must travel along its own facing (the frame of <c>AnimationStream.velocity</c>), show on arrival the pose
    /// <c>AnimationClip.SampleAnimation</c> gives (humanoid targets read off the playable graph's input stream), and not
    /// snap when it blends back to the controller. Nothing is logged (no root-motion frame or target warning).
    /// </summary>
    /// <remarks>
    /// Editor only (it imports the sample's <c>.bvh</c> into a temporary folder under Assets, removed afterwards); the Unity
    /// check compiles it against stubs proven against Unity 6000.0 and com.unity.test-framework 1.4.6, but cannot run it.
    /// </remarks>
    public sealed class HumanoidRootMotionVerification
    {
        private const string Package = "com.deltainterpolator.inbetweening";
        private const string BvhFile = "cmu_09_12_walk_navigate.bvh";
        private const float WalkBeforeRequest = 1.0f;    // seconds of the controller's own walk (evidence for the frame check)
        private const float TargetClipTime = 3.0f;       // the frame of the clip the transition goes to
        private const float Timeout = 5.0f;              // seconds after the request before the test gives up
        private const float PoseToleranceDegrees = 1.0f; // arrival pose vs. SampleAnimation, per bone (float rounding, muscle round trip)
        private const float SidewaysShare = 0.25f;       // travel across the facing, as a share of travel along it

        [UnityTest]
        public IEnumerator AHumanoidBvhFigureTurned90DegreesTravelsTowardItsTargetShowsTheSampledPoseAndDoesNotSnap()
        {
            string folder = AssetDatabase.GUIDToAssetPath(AssetDatabase.CreateFolder("Assets", "DeltaInterpolator Verification"));
            var created = new List<Object>();
            try
            {
                string bvh = folder + "/" + BvhFile;
                File.Copy(Path.GetFullPath("Packages/" + Package + "/Samples~/Demo/" + BvhFile), Path.GetFullPath(bvh));
                AssetDatabase.ImportAsset(bvh);
                GameObject figure = AssetDatabase.LoadAssetAtPath<GameObject>(bvh);
                Assert.That(figure != null, Is.True, bvh + " is imported as a figure by the package's BVH importer");
                AnimationClip? clip = null;
                Avatar? avatar = null;
                foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(bvh))
                {
                    if (o is AnimationClip c) clip = c;
                    if (o is Avatar a) avatar = a;
                }

                Assert.That(clip != null && avatar != null && avatar.isHuman, Is.True, "the CMU figure imports as a humanoid with a clip");
                InbetweenerSettings settings = Settings(folder, clip!);
                AnimatorController controller = AnimatorController.CreateAnimatorControllerAtPathWithClip(folder + "/Controller.controller", clip);

                // The character, its controller's twin (the same controller, no transitions: the controller's own pose and
                // motion each frame) and a hidden copy the clip is sampled onto, all turned 90° and started together.
                GameObject character = Figure(figure!, avatar!, controller, created, visible: true);
                GameObject twin = Figure(figure!, avatar!, controller, created, visible: false);
                GameObject sampled = Figure(figure!, avatar!, null, created, visible: false);
                var inbetweener = character.AddComponent<MotionInbetweener>();
                inbetweener.Settings = settings;
                int arrivalFrame = -1;
                inbetweener.TransitionCompleted += e => { if (e.ReachedTarget) arrivalFrame = Time.frameCount; };

                double start = Time.timeAsDouble;
                while (Time.timeAsDouble - start < WalkBeforeRequest) yield return null;
                Assert.That(inbetweener.State, Is.EqualTo(PlaybackState.Running), inbetweener.FailureReason);
                IReadOnlyList<Transform> bones = inbetweener.Bones;
                Transform[] twinBones = Counterparts(bones, character.transform, twin.transform);
                Transform[] sampledBones = Counterparts(bones, character.transform, sampled.transform);
                Vector3 from = character.transform.position;
                Vector3 facing = character.transform.rotation * new Vector3(0f, 0f, 1f);
                inbetweener.RequestTransition(clip!, TargetClipTime);
                double requested = Time.timeAsDouble;

                // Until the arrival frame has been shown (the coroutine runs after Update, before the frame's animation).
                while (arrivalFrame < 0 || Time.frameCount <= arrivalFrame)
                {
                    Assert.That(Time.timeAsDouble - requested, Is.LessThan(Timeout), "the transition arrives");
                    yield return null;
                }

                Vector3 moved = character.transform.position - from;
                float along = moved.x * facing.x + moved.z * facing.z;
                float across = Math.Abs(moved.x * facing.z - moved.z * facing.x);
                Assert.That(along, Is.GreaterThan(0f), "the character travels along its facing, toward its target");
                Assert.That(across, Is.LessThanOrEqualTo(SidewaysShare * along), "the character is not pushed sideways (the stream velocity's frame)");

                clip!.SampleAnimation(sampled, TargetClipTime);
                for (int b = 1; b < bones.Count; b++)
                {
                    float off = Degrees(bones[b].localRotation, sampledBones[b].localRotation);
                    Assert.That(off, Is.LessThanOrEqualTo(PoseToleranceDegrees), $"{bones[b].name} on arrival vs. AnimationClip.SampleAnimation");
                }

                // The blend-out: each step no bone turns more than 1.25 × (the controller's own turn + the smoothstep's
                // steepest share of the gap left at arrival) + 0.5°.
                var gap = new float[bones.Count];
                var lastShown = new Quaternion[bones.Count];
                var lastTwin = new Quaternion[bones.Count];
                for (int b = 0; b < bones.Count; b++)
                {
                    gap[b] = Degrees(bones[b].localRotation, twinBones[b].localRotation);
                    lastShown[b] = bones[b].localRotation;
                    lastTwin[b] = twinBones[b].localRotation;
                }

                double blendOutEnd = Time.timeAsDouble + settings.BlendOutSeconds + 0.1;
                while (Time.timeAsDouble < blendOutEnd)
                {
                    yield return null;
                    float step = Time.deltaTime;
                    for (int b = 1; b < bones.Count; b++)
                    {
                        float shown = Degrees(lastShown[b], bones[b].localRotation);
                        float own = Degrees(lastTwin[b], twinBones[b].localRotation);
                        float bound = 1.25f * (own + 1.5f * gap[b] * step / settings.BlendOutSeconds) + 0.5f;
                        Assert.That(shown, Is.LessThanOrEqualTo(bound), $"{bones[b].name} turned {shown:F2}° in one step of the blend-out");
                        lastShown[b] = bones[b].localRotation;
                        lastTwin[b] = twinBones[b].localRotation;
                    }
                }

                LogAssert.NoUnexpectedReceived();
            }
            finally
            {
                foreach (Object o in created) if (o != null) Object.DestroyImmediate(o);
                AssetDatabase.DeleteAsset(folder);
            }
        }

        // The settings the Demo uses: the shipped model, Humanoid, CMU joint names, the clip's first frame (a T-pose) as reference.
        private static InbetweenerSettings Settings(string folder, AnimationClip clip)
        {
            var settings = ScriptableObject.CreateInstance<InbetweenerSettings>();
            var s = new SerializedObject(settings);
            s.FindProperty("model").objectReferenceValue = ShippedModelAssets.Create(folder + "/Model.asset");
            s.FindProperty("rig").enumValueIndex = (int)CharacterRigKind.Humanoid;
            s.FindProperty("jointMap").enumValueIndex = (int)BuiltInJointMap.Cmu;
            s.FindProperty("referencePose").enumValueIndex = (int)ReferencePoseSource.ClipFrame;
            s.FindProperty("referenceClip").objectReferenceValue = clip;
            s.FindProperty("referenceClipTime").floatValue = 0f;
            s.ApplyModifiedPropertiesWithoutUndo();
            return settings;
        }

        private static GameObject Figure(GameObject figure, Avatar avatar, RuntimeAnimatorController? controller, List<Object> created, bool visible)
        {
            GameObject go = Object.Instantiate(figure);
            created.Add(go);
            go.transform.rotation = Quaternion.Euler(0f, 90f, 0f);
            Animator animator = go.GetComponent<Animator>();
            if (animator == null) animator = go.AddComponent<Animator>();
            animator.avatar = avatar;
            animator.runtimeAnimatorController = controller;
            animator.applyRootMotion = true;
            if (!visible) foreach (Renderer r in go.transform.GetComponentsInChildren<Renderer>(true)) r.enabled = false;
            return go;
        }

        // The same bones, by their path under the figure's root, in another instance of the figure.
        private static Transform[] Counterparts(IReadOnlyList<Transform> bones, Transform root, Transform other)
        {
            var found = new Transform[bones.Count];
            for (int b = 0; b < bones.Count; b++)
            {
                string path = bones[b].name;
                for (Transform t = bones[b].parent; t != root && t != null; t = t.parent) path = t.name + "/" + path;
                found[b] = other.Find(path);
                if (found[b] == null) throw new InvalidOperationException($"{path} is missing from a copy of the figure");
            }

            return found;
        }

        private static float Degrees(Quaternion a, Quaternion b)
        {
            float dot = Math.Abs(a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w);
            return 2f * (float)Math.Acos(Math.Min(1f, dot)) * 180f / (float)Math.PI;
        }
    }
}
#endif
