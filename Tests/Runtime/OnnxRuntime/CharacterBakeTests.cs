using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Characters;
using System;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The editor baker's Core path (issue 15, item 4): a character that is not the model's rig — bones renamed and
    /// reached through a JSON map, other local bone frames, metres under an FBX-like armature (turned, scale 0.01) —
    /// given only its key poses as Unity's transforms hold them, bakes through <see cref="CharacterBake"/> (the
    /// component's map) to the world motion the CLI's <see cref="InbetweenBake"/> gives on the original BVH, and
    /// comes back as bone transforms (<see cref="CharacterPoseTrack.ReadUnityPose"/>) that rebuild it.
    /// </summary>
    [TestFixture]
    public sealed class CharacterBakeTests
    {
        private const double Metres = 0.01;

        /// <param name="lockFeet">Both paths with foot locking (the window's "Lock planted feet", `bake --feet lock`).</param>
        [TestCase(false)]
        [TestCase(true)]
        public void TheEditorPathOnAnotherRigBakesWhatTheCliBakes(bool lockFeet)
        {
            MotionClip original = TwoRigBakeTests.DemoWalk(); // the T-pose and 4 s of walking
            using Inbetweener model = TwoRigBakeTests.ShippedModel();
            FootLockSettings? feet = lockFeet ? new FootLockSettings() : null;
            BakeMethod[] Methods() => new[] { BakeMethod.Model(model, feet: feet), BakeMethod.Slerp(lockFeet) };

            // The CLI: `bake --reference-frame 0` on the BVH.
            IRigRetargeting cli = RigRetargeting.For(model.Contract, original, "cmu.bvh", referenceFrame: 0);
            int[] keys = BakeKeys.Every(60, original, 1, model.Contract);
            BakeRun expected = InbetweenBake.Run(original, keys, cli, Methods());
            if (lockFeet)
            {
                // Locking changes this walk's bake (its feet are planted between keys), so the comparison below covers it.
                BakeRun unlocked = InbetweenBake.Run(original, keys, cli, new[] { BakeMethod.Model(model) });
                double[] a = TwoRigBakeTests.World(expected["Model"].OnRig), b = TwoRigBakeTests.World(unlocked["Model"].OnRig);
                double moved = 0;
                for (int i = 0; i < a.Length; i++) moved = Math.Max(moved, Math.Abs(a[i] - b[i]));
                Assert.That(moved / cli.LegLength, Is.GreaterThan(1e-2), "locking moved some joint by over 1 % of leg length");
            }

            // The editor: the same motion on another rig, its key poses read off the transforms.
            (MotionClip rebuilt, string json) = TwoRigBakeTests.Rebuild(original, ((MappedRig)cli).Map);
            var armature = new RootFrame(new Vector3D(0.3, 0, -0.2), Quaternions.FromAxisAngle(new Vector3D(0, 1, 0), 0.7), 0.01);
            CharacterRig rig = Character(rebuilt, armature);
            var track = new CharacterPoseTrack(rig, rebuilt.FrameCount, rebuilt.FrameTime);
            int n = rig.BoneNames.Count;
            var root = new double[3];
            var rotations = new double[4 * n];
            foreach (int k in keys)
            {
                UnityPose(rebuilt, k, armature, root, rotations);
                track.SetUnityPose(k, root, rotations);
            }

            var progress = new Counter();
            BakeRun actual = CharacterBake.Run(model.Contract, track, JointMap.FromJson(json, "rig-b-map.json"), Methods(), progress,
                maxBoneDeviationDegrees: 30); // CMU's T-pose frame holds the right shoulder 26° from the model's
            Assert.That(progress.Last.Completed, Is.EqualTo(progress.Last.Total), "progress reaches every gap of every method");
            Assert.That(progress.Last.Total, Is.EqualTo(2 * (keys.Length - 1)));

            double leg = cli.LegLength;
            Assert.That(actual.Rig.LegLength / Metres, Is.EqualTo(leg).Within(1e-6 * leg), "leg length in the character's units");
            foreach (string method in new[] { "Model", "SLERP" })
            {
                MotionClip onRig = actual[method].OnRig;
                // Back through the bones' transforms, as the window writes curves from them.
                var back = new CharacterPoseTrack(rig, onRig.FrameCount, onRig.FrameTime);
                for (int f = 0; f < onRig.FrameCount; f++)
                {
                    CharacterPoseTrack.ReadUnityPose(rig, onRig, f, root, rotations);
                    back.SetUnityPose(f, root, rotations);
                }

                double[] pa = TwoRigBakeTests.World(expected[method].OnRig);
                double[] pb = TwoRigBakeTests.World(back.Motion);
                Assert.That(pb.Length, Is.EqualTo(pa.Length));
                double worst = 0;
                for (int i = 0; i < pa.Length; i++) worst = Math.Max(worst, Math.Abs(pa[i] - pb[i] / Metres));
                TestContext.WriteLine($"{method}: largest world position difference from the CLI's bake {worst / leg:E2} leg lengths");
                Assert.That(worst / leg, Is.LessThan(1e-3), $"{method}: largest world position difference {worst / leg:E2} leg lengths");
            }

            // The comparison resolves what matters: the two methods' bakes lie far more than 1e-3 leg lengths apart.
            double[] model0 = TwoRigBakeTests.World(expected["Model"].OnRig), slerp = TwoRigBakeTests.World(actual["SLERP"].OnRig);
            double apart = 0;
            for (int i = 0; i < model0.Length; i++) apart = Math.Max(apart, Math.Abs(model0[i] - slerp[i] / Metres));
            TestContext.WriteLine($"Model against SLERP: {apart / leg:E2} leg lengths");
            Assert.That(apart / leg, Is.GreaterThan(1e-2));
        }

        /// <summary>The rig as the Unity layer would collect it: Unity's space, bones under <paramref name="armature"/>, frame 0 (a T-pose) the reference.</summary>
        private static CharacterRig Character(MotionClip clip, RootFrame armature)
        {
            Skeleton s = clip.Skeleton;
            int n = s.JointCount;
            var positions = new double[3 * n];
            for (int b = 0; b < n; b++)
            {
                Vector3D offset = Vector3D.Read(s.OffsetSpan, 3 * b);
                Vector3D unity = Handedness.PositionToUnity(offset);
                (b == 0 ? armature.PointFromParent(unity) : (1 / armature.Scale) * unity).Write(positions, 3 * b);
            }

            var root = new double[3];
            var rotations = new double[4 * n];
            UnityPose(clip, 0, armature, root, rotations);
            return new CharacterRig("rig-b", s.Names, s.Parents, positions, rotations, armature);
        }

        /// <summary>Frame <paramref name="frame"/> of a right-handed clip as Unity's transforms hold it under <paramref name="armature"/>.</summary>
        private static void UnityPose(MotionClip clip, int frame, RootFrame armature, double[] root, double[] rotations)
        {
            int n = clip.Skeleton.JointCount;
            for (int b = 0; b < n; b++)
            {
                QuaternionD q = Handedness.RotationToUnity(QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(frame, b)));
                (b == 0 ? armature.RotationFromParent(q) : q).Write(rotations, 4 * b);
            }

            armature.PointFromParent(Handedness.PositionToUnity(Vector3D.Read(clip.LocalPositions, clip.PositionIndex(frame, 0)))).Write(root, 0);
        }

        private sealed class Counter : IProgress<StageProgress>
        {
            public StageProgress Last { get; private set; }

            public void Report(StageProgress value) => Last = value;
        }
    }
}
