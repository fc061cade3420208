using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Tests.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// In-betweens written into the clip being keyed (issue 28, item 3), on a real clip: the Demo sample's walk keyed
    /// every 15 model frames on a character under an FBX-like armature. The fill's keys equal the Core bake of the
    /// same key poses (read straight from the walk, not from the curves) to 1e-5, the animator's keys stay as they
    /// were, Euler curves stay continuous with their neighbouring keys, the edit applies and inverts exactly, and a
    /// range limits it.
    /// </summary>
    [TestFixture]
    public sealed class KeyFillTests
    {
        private static readonly int[] Keys = { 3, 18, 33, 48, 63, 78, 93, 108 };
        private const double MaxBoneDeviation = 30; // CMU's T-pose frame holds the right shoulder 26° from the model's

        private Inbetweener? _model;

        [OneTimeSetUp]
        public void Load() => _model = TwoRigBakeTests.ShippedModel();

        [OneTimeTearDown]
        public void Unload() => _model?.Dispose();

        [TestCase(false)]
        [TestCase(true)]
        public void FilledKeysEqualTheCoreBakeAndTheAnimatorsKeysStay(bool euler)
        {
            KeyedClipFixture clip = KeyedClipFixture.Create(Keys, euler);
            ModelContract contract = _model!.Contract;
            KeyFillPlan plan = KeyFill.Plan("walk", clip.Curves, clip.Length, contract.FramesPerSecond);
            Assert.That(plan.KeyFrames, Is.EqualTo(Keys));
            Assert.That(plan.Kind, Is.EqualTo(KeyFillClipKind.Transform));
            (KeyFillEdit edit, BakeRun _) = KeyFillBake.Run(contract, plan, clip.Curves, clip.Rig, null, clip.BonePaths, clip.ScenePose(), BakeMethod.Model(_model), MaxBoneDeviation);
            IReadOnlyList<KeyedCurve> after = edit.Apply(clip.Curves);

            // The expectation: the Core bake of the walk's own key poses (not read off the curves).
            BakeRun expected = CharacterBake.Run(contract, clip.TrackFromWalk(Keys), null, new[] { BakeMethod.Model(_model) }, null, MaxBoneDeviation);
            BakeRun slerp = CharacterBake.Run(contract, clip.TrackFromWalk(Keys), null, new[] { BakeMethod.Slerp() }, null, MaxBoneDeviation);
            CharacterRig rig = clip.Rig;
            int n = rig.BoneNames.Count;
            int span = Keys[Keys.Length - 1] - Keys[0] + 1;
            var root = new double[3];
            var rotations = new double[4 * n];
            var slerpRotations = new double[4 * n];
            double worstRotation = 0, worstPosition = 0, modelFromSlerp = 0, largestStep = 0;
            for (int i = 0; i < clip.Curves.Count; i++)
            {
                KeyedCurve before = clip.Curves[i], now = after[i];
                Assert.That(now.Path + now.Property, Is.EqualTo(before.Path + before.Property));
                // Every key of the animator's is still there, every field the same.
                foreach (CurveKey key in before.Keys) Assert.That(Contains(now, key), Is.True, $"{before}: key {key} kept");
                if (before.Property == "m_LocalScale.x")
                {
                    Assert.That(now, Is.SameAs(before), "a curve that is no pose is not touched");
                    continue;
                }

                Assert.That(now.Keys.Count, Is.EqualTo(span), $"{before}: a key on every model frame of the span");
                if (before.Property.StartsWith("localEulerAnglesRaw", StringComparison.Ordinal))
                {
                    for (int k = 1; k < now.Keys.Count; k++)
                    {
                        double step = Math.Abs(now.Keys[k].Value - now.Keys[k - 1].Value);
                        largestStep = Math.Max(largestStep, step);
                    }
                }
            }

            for (int f = Keys[0]; f <= Keys[Keys.Length - 1]; f++)
            {
                if (Array.IndexOf(Keys, f) >= 0) continue;
                CharacterPoseTrack.ReadUnityPose(rig, expected.Methods[0].OnRig, f - Keys[0], root, rotations);
                CharacterPoseTrack.ReadUnityPose(rig, slerp.Methods[0].OnRig, f - Keys[0], root.AsSpan().ToArray(), slerpRotations);
                for (int b = 0; b < n; b++)
                {
                    QuaternionD want = QuaternionD.Read(rotations, 4 * b);
                    QuaternionD got = euler
                        ? KeyFill_UnityEuler(ValueAt(after, clip.BonePaths[b], "localEulerAnglesRaw.x", f), ValueAt(after, clip.BonePaths[b], "localEulerAnglesRaw.y", f), ValueAt(after, clip.BonePaths[b], "localEulerAnglesRaw.z", f))
                        : new QuaternionD(ValueAt(after, clip.BonePaths[b], "m_LocalRotation.w", f), ValueAt(after, clip.BonePaths[b], "m_LocalRotation.x", f),
                            ValueAt(after, clip.BonePaths[b], "m_LocalRotation.y", f), ValueAt(after, clip.BonePaths[b], "m_LocalRotation.z", f));
                    worstRotation = Math.Max(worstRotation, Distance(want, got));
                    modelFromSlerp = Math.Max(modelFromSlerp, Distance(want, QuaternionD.Read(slerpRotations, 4 * b)));
                }

                for (int c = 0; c < 3; c++) worstPosition = Math.Max(worstPosition, Math.Abs(root[c] - ValueAt(after, clip.BonePaths[0], "m_LocalPosition." + "xyz"[c], f)) / Math.Max(1, Math.Abs(root[c])));
            }

            double leastDot = 1;
            if (!euler)
            {
                // Quaternion curves interpolate components: each key in the hemisphere of the one before, keys and filled alike.
                foreach (string bone in clip.BonePaths)
                {
                    for (int f = Keys[0] + 1; f <= Keys[Keys.Length - 1]; f++)
                    {
                        double dot = 0;
                        foreach (char c in "xyzw") dot += ValueAt(after, bone, "m_LocalRotation." + c, f) * ValueAt(after, bone, "m_LocalRotation." + c, f - 1);
                        leastDot = Math.Min(leastDot, dot);
                    }
                }

                Assert.That(leastDot, Is.GreaterThan(0), "no quaternion key flips to −q");
            }

            TestContext.WriteLine($"least dot of neighbouring quaternion keys {leastDot:0.####}");
            TestContext.WriteLine($"{(euler ? "Euler" : "quaternion")} curves: {edit.FilledKeys} keys filled; largest rotation difference from the Core bake {worstRotation:E2} (quaternion components), root position {worstPosition:E2} (relative); model against SLERP {modelFromSlerp:E2}; largest Euler step between neighbouring keys {largestStep:0.##}°");
            Assert.That(worstRotation, Is.LessThan(1e-5));
            Assert.That(worstPosition, Is.LessThan(1e-5));
            Assert.That(modelFromSlerp, Is.GreaterThan(1e-2), "the comparison resolves the model from SLERP");
            if (euler) Assert.That(largestStep, Is.LessThan(45), "no Euler key flips by a turn from its neighbour (a walk turns a joint far less than 45° in 1/30 s)");
        }

        [Test]
        public void ApplyThenInvertGivesTheOriginalExactly()
        {
            KeyedClipFixture clip = KeyedClipFixture.Create(Keys, euler: true);
            (KeyFillEdit edit, IReadOnlyList<KeyedCurve> after) = Fill(clip, null);
            Assert.That(edit.Changes.Count, Is.EqualTo(clip.Curves.Count - 1), "every pose curve changes; the scale curve does not");
            IReadOnlyList<KeyedCurve> back = edit.Inverse().Apply(after);
            for (int i = 0; i < clip.Curves.Count; i++)
            {
                Assert.That(back[i].SameAs(clip.Curves[i]), Is.True, $"{clip.Curves[i]} restored bit for bit");
                Assert.That(after[i].SameAs(clip.Curves[i]), Is.EqualTo(clip.Curves[i].Property == "m_LocalScale.x"), $"{clip.Curves[i]} changed by the fill");
            }

            // The edit refuses a clip that changed since it was made (and the inverse refuses the original).
            var ex = Assert.Throws<KeyFillException>(() => edit.Inverse().Apply(clip.Curves));
            Assert.That(ex!.ParamName, Is.EqualTo("curves"));
            Assert.That(ex.Message, Does.Contain("changed since the fill was planned; expected"));
        }

        [Test]
        public void ARangeFillsOnlyTheGapsInsideIt()
        {
            KeyedClipFixture clip = KeyedClipFixture.Create(Keys, euler: false);
            var range = new FillRange(33 / KeyedClipFixture.ModelFps, 63 / KeyedClipFixture.ModelFps);
            (KeyFillEdit edit, IReadOnlyList<KeyedCurve> after) = Fill(clip, range);
            Assert.That(edit.FilledKeys, Is.EqualTo(28 * (clip.Curves.Count - 1)), "frames 34–47 and 49–62 (48 is a key)");
            for (int i = 0; i < clip.Curves.Count; i++)
            {
                var added = new List<float>();
                foreach (CurveKey key in after[i].Keys)
                {
                    if (!Contains(clip.Curves[i], key)) added.Add(key.Time);
                }

                foreach (float t in added) Assert.That(t * KeyedClipFixture.ModelFps, Is.GreaterThan(33.5).And.LessThan(62.5), $"{clip.Curves[i]}: a key added outside the range");
                Assert.That(after[i].Keys.Count - clip.Curves[i].Keys.Count, Is.EqualTo(added.Count));
            }
        }

        private (KeyFillEdit, IReadOnlyList<KeyedCurve>) Fill(KeyedClipFixture clip, FillRange? range)
        {
            ModelContract contract = _model!.Contract;
            KeyFillPlan plan = KeyFill.Plan("walk", clip.Curves, clip.Length, contract.FramesPerSecond, range);
            (KeyFillEdit edit, BakeRun _) = KeyFillBake.Run(contract, plan, clip.Curves, clip.Rig, null, clip.BonePaths, clip.ScenePose(), BakeMethod.Slerp(), MaxBoneDeviation);
            return (edit, edit.Apply(clip.Curves));
        }

        private static bool Contains(KeyedCurve curve, CurveKey key)
        {
            foreach (CurveKey k in curve.Keys)
            {
                if (k.Equals(key)) return true;
            }

            return false;
        }

        private static double ValueAt(IReadOnlyList<KeyedCurve> curves, string path, string property, int frame)
        {
            foreach (KeyedCurve c in curves)
            {
                if (c.Path != path || c.Property != property) continue;
                foreach (CurveKey k in c.Keys)
                {
                    if (Math.Abs(k.Time * KeyedClipFixture.ModelFps - frame) < 1e-3) return k.Value;
                }

                Assert.Fail($"{c} has no key on frame {frame}");
            }

            Assert.Fail($"no curve {path}:{property}");
            return 0;
        }

        // Unity's Quaternion.Euler: z, then x, then y about the parent's axes.
        private static QuaternionD KeyFill_UnityEuler(double x, double y, double z) => Quaternions.FromEulerDegrees(y, x, z, EulerOrder.Yxz);

        /// <summary>The largest component difference of two rotations, q or −q.</summary>
        private static double Distance(QuaternionD a, QuaternionD b)
        {
            double plus = Math.Max(Math.Max(Math.Abs(a.W - b.W), Math.Abs(a.X - b.X)), Math.Max(Math.Abs(a.Y - b.Y), Math.Abs(a.Z - b.Z)));
            double minus = Math.Max(Math.Max(Math.Abs(a.W + b.W), Math.Abs(a.X + b.X)), Math.Max(Math.Abs(a.Y + b.Y), Math.Abs(a.Z + b.Z)));
            return Math.Min(plus, minus);
        }
    }
}
