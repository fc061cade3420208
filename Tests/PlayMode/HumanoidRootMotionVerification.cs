#if UNITY_EDITOR
#nullable enable
using System;
using System.Collections;
using System.Collections.Generic;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Unity;
using NUnit.Framework;
using UnityEditor.Animations;
using UnityEngine;
using UnityEngine.TestTools;

namespace DeltaInterpolator.Tests.PlayMode
{
    /// <summary>
    /// What the engine does with the package, checked in the real engine (Test Runner → PlayMode; steps in
    /// <c>Documentation~/unity-verification.md</c>): the package's BVH importer turns a Demo sample clip into a humanoid
    /// figure, which walks with root motion on, turned 90° from the world's +Z. Sent to a later frame of its clip, it must
    /// show on arrival the pose <c>AnimationClip.SampleAnimation</c> gives (humanoid targets read off the playable graph's
    /// input stream) and not snap when it blends back to the controller; sent to a pose 1 m ahead, it must travel there
    /// along its facing, not sideways (the frame of <c>AnimationStream.velocity</c>). Nothing is logged (no root-motion
    /// frame or target warning).
    /// </summary>
    /// <remarks>
    /// Editor only (it imports the sample's <c>.bvh</c> into a temporary folder under Assets, removed afterwards); the Unity
    /// check compiles it against stubs proven against Unity 6000.0 and com.unity.test-framework 1.4.6, but cannot run it.
    /// </remarks>
    public sealed class HumanoidRootMotionVerification
    {
        private const string BvhFile = "cmu_09_12_walk_navigate.bvh";
        private const float WalkBeforeRequest = 1.0f;    // seconds of the controller's own walk (evidence for the frame check)
        private const float TargetClipTime = 3.0f;       // the frame of the clip the transition goes to
        private const float Timeout = 5.0f;              // seconds after the request before the test gives up
        private const float PoseToleranceDegrees = 1.0f; // arrival pose vs. SampleAnimation, per bone (float rounding, muscle round trip)
        private const float Ahead = 1.0f;                // metres: the pose target in front of the character
        private const float Reach = 0.1f;                // metres: the hips on the pose target (horizontally) on arrival
        private const float Sideways = 0.1f;             // metres the character may stray across its facing meanwhile
        private const float HandReach = 0.02f;           // metres: the hand is on its IK goal

        [UnityTest]
        public IEnumerator AHumanoidBvhFigureTurned90DegreesTravelsTowardItsTargetShowsTheSampledPoseAndDoesNotSnap()
        {
            var rig = Rig.Import();
            try
            {
                // The character, its controller's twin (the same controller, no transitions: the controller's own pose and
                // motion each frame) and a hidden copy the clip is sampled onto, all turned 90° and started together.
                GameObject character = rig.Figure(rig.Controller, visible: true, rootMotion: true);
                GameObject twin = rig.Figure(rig.Controller, visible: false, rootMotion: true);
                GameObject sampled = rig.Figure(null, visible: false, rootMotion: true);
                var inbetweener = character.AddComponent<MotionInbetweener>();
                inbetweener.Settings = rig.Settings;
                int arrivalFrame = -1;
                inbetweener.TransitionCompleted += e => { if (e.ReachedTarget) arrivalFrame = Time.frameCount; };

                double start = Time.timeAsDouble;
                while (Time.timeAsDouble - start < WalkBeforeRequest) yield return null;
                Assert.That(inbetweener.State, Is.EqualTo(PlaybackState.Running), inbetweener.FailureReason);
                IReadOnlyList<Transform> bones = inbetweener.Bones;
                Transform[] twinBones = Counterparts(bones, character.transform, twin.transform);
                Transform[] sampledBones = Counterparts(bones, character.transform, sampled.transform);
                inbetweener.RequestTransition(rig.Clip, TargetClipTime);
                double requested = Time.timeAsDouble;

                // Until the arrival frame has been shown (the coroutine runs after Update, before the frame's animation).
                while (arrivalFrame < 0 || Time.frameCount <= arrivalFrame)
                {
                    Assert.That(Time.timeAsDouble - requested, Is.LessThan(Timeout), "the clip transition arrives");
                    yield return null;
                }

                rig.Clip.SampleAnimation(sampled, TargetClipTime);
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

                float blendOut = rig.Settings.BlendOutSeconds;
                double blendOutEnd = Time.timeAsDouble + blendOut + 0.1;
                while (Time.timeAsDouble < blendOutEnd)
                {
                    yield return null;
                    float step = Time.deltaTime;
                    for (int b = 1; b < bones.Count; b++)
                    {
                        float shown = Degrees(lastShown[b], bones[b].localRotation);
                        float own = Degrees(lastTwin[b], twinBones[b].localRotation);
                        float bound = 1.25f * (own + 1.5f * gap[b] * step / blendOut) + 0.5f;
                        Assert.That(shown, Is.LessThanOrEqualTo(bound), $"{bones[b].name} turned {shown:F2}° in one step of the blend-out");
                        lastShown[b] = bones[b].localRotation;
                        lastTwin[b] = twinBones[b].localRotation;
                    }
                }

                // A pose 1 m ahead of the hips (the root bone's position is given where the character stands now): the
                // character walks there along its facing (+X in the world), not sideways, whatever frame the stream's
                // velocity is in, once the run-time check has seen the controller walk on its own.
                double walkOn = Time.timeAsDouble + WalkBeforeRequest;
                while (Time.timeAsDouble < walkOn) yield return null;
                var rotations = new Quaternion[bones.Count];
                for (int b = 0; b < bones.Count; b++) rotations[b] = sampledBones[b].localRotation;
                Vector3 from = character.transform.position;
                Quaternion facing = character.transform.rotation;
                Vector3 forward = facing * new Vector3(0f, 0f, 1f);
                Vector3 targetLocal = bones[0].localPosition + new Vector3(0f, 0f, Ahead);
                Vector3 target = from + facing * targetLocal;
                arrivalFrame = -1;
                inbetweener.RequestTransition(targetLocal, rotations);
                requested = Time.timeAsDouble;
                float strayed = 0f;
                while (arrivalFrame < 0 || Time.frameCount <= arrivalFrame)
                {
                    Assert.That(Time.timeAsDouble - requested, Is.LessThan(Timeout), "the pose transition arrives");
                    yield return null;
                    Vector3 moved = character.transform.position - from;
                    strayed = Math.Max(strayed, Math.Abs(moved.x * forward.z - moved.z * forward.x));
                }

                Vector3 miss = bones[0].position - target;
                float missed = (float)Math.Sqrt(miss.x * miss.x + miss.z * miss.z);
                Assert.That(missed, Is.LessThanOrEqualTo(Reach), "the hips arrive on the pose target 1 m ahead");
                Assert.That(strayed, Is.LessThanOrEqualTo(Sideways), "the character travels toward its target, not sideways (the stream velocity's frame)");
                LogAssert.NoUnexpectedReceived();
            }
            finally
            {
                rig.Dispose();
            }
        }

        /// <summary>
        /// What <c>unity-verification.md</c> says of the controller's IK pass: it belongs to the Animator Controller's output,
        /// under the transition layer, so an <c>OnAnimatorIK</c> hand goal is reached before a transition, not while the
        /// layer's weight is 1 (the transition's pose is shown), and again after the blend-out. A failure here means that
        /// page is wrong about where Unity solves the controller's IK.
        /// </summary>
        [UnityTest]
        public IEnumerator TheControllersIkPassIsUnderTheTransitionLayer()
        {
            var rig = Rig.Import();
            try
            {
                AnimatorControllerLayer[] layers = rig.Controller.layers;
                layers[0].iKPass = true;
                rig.Controller.layers = layers;
                GameObject character = rig.Figure(rig.Controller, visible: true, rootMotion: false);
                var goal = character.AddComponent<HandGoal>();
                var inbetweener = character.AddComponent<MotionInbetweener>();
                inbetweener.Settings = rig.Settings;
                int arrivalFrame = -1;
                inbetweener.TransitionCompleted += e => { if (e.ReachedTarget) arrivalFrame = Time.frameCount; };
                Transform hand = character.GetComponent<Animator>().GetBoneTransform(HumanBodyBones.LeftHand);

                double start = Time.timeAsDouble;
                while (Time.timeAsDouble - start < WalkBeforeRequest) yield return null;
                // A goal a little in front of where the hand is: within reach while the character walks in place.
                goal.Goal = hand.position + character.transform.rotation * new Vector3(0f, 0f, 0.1f);
                goal.Active = true;
                for (int i = 0; i < 3; i++) yield return null;
                Assert.That(Distance(hand.position, goal.Goal), Is.LessThan(HandReach), "the IK pass puts the hand on its goal before a transition");

                inbetweener.RequestTransition(rig.Clip, TargetClipTime);
                double requested = Time.timeAsDouble;
                while (arrivalFrame < 0 || Time.frameCount <= arrivalFrame)
                {
                    Assert.That(Time.timeAsDouble - requested, Is.LessThan(Timeout), "the transition arrives");
                    yield return null;
                }

                Assert.That(Distance(hand.position, goal.Goal), Is.GreaterThan(HandReach), "at weight 1 the transition's pose is shown, not the controller's IK");
                double end = Time.timeAsDouble + rig.Settings.BlendOutSeconds + 0.2;
                while (Time.timeAsDouble < end) yield return null;
                Assert.That(Distance(hand.position, goal.Goal), Is.LessThan(HandReach), "after the blend-out the controller's IK shows again");
            }
            finally
            {
                rig.Dispose();
            }
        }

        /// <summary>The imported figure, its clip and avatar, Demo-like settings and a controller, in a temporary folder.</summary>
        private sealed class Rig : DemoFigureImport
        {
            private Rig()
                : base("DeltaInterpolator Verification")
            {
            }

            public AnimationClip Clip { get; private set; } = null!;

            public InbetweenerSettings Settings { get; private set; } = null!;

            public AnimatorController Controller { get; private set; } = null!;

            /// <summary>Imports the Demo's walk with the package's BVH importer into Assets/DeltaInterpolator Verification.</summary>
            public static Rig Import()
            {
                var rig = new Rig();
                Dictionary<string, AnimationClip> clips = rig.ImportBvh(BvhFile, out GameObject figure, out Avatar avatar);
                rig.FigureAsset = figure;
                rig.FigureAvatar = avatar;
                foreach (AnimationClip c in clips.Values) rig.Clip = c; // uncut: the one clip of the whole take
                Assert.That(rig.Clip != null && avatar != null && avatar.isHuman, Is.True, "the CMU figure imports as a humanoid with a clip");
                // The settings the Demo uses: Humanoid, the clip's first frame (a T-pose) as reference.
                rig.Settings = rig.DemoSettings(CharacterRigKind.Humanoid, rig.Clip!);
                rig.Controller = AnimatorController.CreateAnimatorControllerAtPathWithClip(rig.Folder + "/Controller.controller", rig.Clip);
                return rig;
            }

            /// <summary>An instance of the figure turned 90° from the world's +Z, on <paramref name="controller"/> (none: still).</summary>
            public GameObject Figure(RuntimeAnimatorController? controller, bool visible, bool rootMotion)
            {
                // At the origin, where the importer builds the figure's root.
                GameObject go = Figure(new Vector3(0f, 0f, 0f), 90f, controller, rootMotion);
                if (!visible) foreach (Renderer r in go.transform.GetComponentsInChildren<Renderer>(true)) r.enabled = false;
                return go;
            }
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

        private static float Distance(Vector3 a, Vector3 b)
        {
            Vector3 d = a - b;
            return (float)Math.Sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        }

        private static float Degrees(Quaternion a, Quaternion b)
        {
            float dot = Math.Abs(a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w);
            return 2f * (float)Math.Acos(Math.Min(1f, dot)) * 180f / (float)Math.PI;
        }
    }
}
#endif
