using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    /// <summary>
    /// The fill's refusals (issue 28, item 3) under the refusal contract: an exception naming the argument at fault
    /// (<c>curves</c> or <c>range</c>) with one line, <c>CLIP: what; expected …</c>, thrown before any model runs.
    /// Also the humanoid write: keys kept, the recording's frames written, the body rotation kept in one hemisphere.
    /// </summary>
    [TestFixture]
    public sealed class KeyFillRefusalTests
    {
        private const double Fps = 30;

        private static KeyedCurve Curve(string path, string property, params (float Time, float Value)[] keys)
        {
            var list = new CurveKey[keys.Length];
            for (int i = 0; i < keys.Length; i++) list[i] = new CurveKey(keys[i].Time, keys[i].Value, 0, 0);
            return new KeyedCurve(path, property, list);
        }

        private static List<KeyedCurve> Hips(params (float, float)[] keys) => new List<KeyedCurve> { Curve("Armature/Hips", "m_LocalPosition.y", keys) };

        private static void AssertRefused(TestDelegate fill, string param, string problem)
        {
            var e = Assert.Throws<KeyFillException>(fill);
            Assert.That(e!.ParamName, Is.EqualTo(param));
            Assert.That(e.Message, Does.StartWith("clip: "));
            Assert.That(e.Message, Does.Contain(problem));
            Assert.That(e.Message.Split(new[] { "; expected" }, StringSplitOptions.None).Length, Is.EqualTo(2), e.Message);
            Assert.That(e.Message, Does.Not.Contain("\n"));
        }

        [Test]
        public void AnEmptyClipIsRefused()
        {
            AssertRefused(() => KeyFill.Plan("clip", new List<KeyedCurve>(), 1, Fps), "curves", "no keyed rotation, position or muscle curve");
            // Curves that are no pose (scale) hold no key poses either.
            AssertRefused(() => KeyFill.Plan("clip", new List<KeyedCurve> { Curve("Armature/Hips", "m_LocalScale.x", (0f, 1f), (1f, 2f)) }, 1, Fps), "curves", "no keyed rotation");
        }

        [Test]
        public void OneKeyFrameIsRefused() =>
            AssertRefused(() => KeyFill.Plan("clip", Hips((0.5f, 1f)), 1, Fps), "curves", "keys on one frame only");

        [Test]
        public void KeysWithoutAGapAreRefused() =>
            AssertRefused(() => KeyFill.Plan("clip", Hips((0f, 1f), (1 / 30f, 2f)), 1, Fps), "curves", "no frame lies between the keys");

        [Test]
        public void TwoKeysOnOneModelFrameAreRefused() =>
            AssertRefused(() => KeyFill.Plan("clip", Hips((0f, 1f), (0.5f, 1f), (0.51f, 2f), (1f, 2f)), 1, Fps), "curves", "fall on one frame (15)");

        [Test]
        public void NonFiniteKeysAreRefused() =>
            AssertRefused(() => KeyFill.Plan("clip", Hips((0f, 1f), (1f, float.NaN)), 1, Fps), "curves", "value NaN");

        [Test]
        public void TransformAndHumanoidCurvesTogetherAreRefused()
        {
            List<KeyedCurve> curves = Hips((0f, 1f), (1f, 2f));
            curves.Add(Curve("", "RootT.y", (0f, 1f), (1f, 2f)));
            AssertRefused(() => KeyFill.Plan("clip", curves, 1, Fps), "curves", "both transform curves and humanoid");
        }

        [TestCase(-0.5, 0.5)]
        [TestCase(0.5, 1.5)]
        [TestCase(0.8, 0.2)]
        [TestCase(double.NaN, 0.5)]
        public void ARangeOutsideTheClipIsRefused(double start, double end) =>
            AssertRefused(() => KeyFill.Plan("clip", Hips((0f, 1f), (1f, 2f)), 1, Fps, new FillRange(start, end)), "range", "is not inside the clip's 0–1 s");

        [Test]
        public void ARangeWithFewerThanTwoKeysIsRefused()
        {
            AssertRefused(() => KeyFill.Plan("clip", Hips((0f, 1f), (1f, 2f)), 1, Fps, new FillRange(0.2, 0.8)), "range", "holds 0 key frames");
            AssertRefused(() => KeyFill.Plan("clip", Hips((0f, 1f), (1f, 2f)), 1, Fps, new FillRange(0.5, 1)), "range", "holds 1 key frame");
            // Two keys inside a range but next to each other: nothing to fill there.
            AssertRefused(() => KeyFill.Plan("clip", Hips((0f, 1f), (0.5f, 1f), (16 / 30f, 2f), (1f, 2f)), 1, Fps, new FillRange(0.4, 0.6)), "range", "no frame lies between the keys of the range");
        }

        [Test]
        public void KeysOutsideTheRangeAreNotTheFillsKeys()
        {
            KeyFillPlan plan = KeyFill.Plan("clip", Hips((0f, 1f), (0.5f, 1f), (1f, 2f)), 1, Fps, new FillRange(0.5, 1));
            Assert.That(plan.KeyFrames, Is.EqualTo(new[] { 15, 30 }));
            Assert.That(plan.MissingFrames, Is.EqualTo(14));
        }

        [TestCase("Armature/Prop", "m_LocalRotation", "is not one of cmu-character's bones")]
        [TestCase("BONE", "m_LocalRotationPartial", "has some of its m_LocalRotation.x/y/z/w curves but not all")]
        [TestCase("BONE", "both", "has both m_LocalRotation and localEulerAnglesRaw curves")]
        [TestCase("BONE", "m_LocalPosition", "which is not the root bone")]
        [TestCase("BONE", "localEulerAngles", "is a localEulerAngles curve")]
        public void CurvesTheRigCannotMapAreRefused(string path, string kind, string problem)
        {
            KeyedClipFixture clip = KeyedClipFixture.Create(new[] { 0, 10 }, euler: false);
            if (path == "BONE") path = clip.BonePaths[3];
            var curves = new List<KeyedCurve>(clip.Curves);
            curves.RemoveAll(c => c.Path == path);
            switch (kind)
            {
                case "m_LocalRotation":
                    foreach (char c in "xyzw") curves.Add(Curve(path, "m_LocalRotation." + c, (0f, 0.5f), (1 / 3f, 0.5f)));
                    break;
                case "m_LocalRotationPartial":
                    foreach (char c in "xyz") curves.Add(Curve(path, "m_LocalRotation." + c, (0f, 0f), (1 / 3f, 0f)));
                    break;
                case "both":
                    foreach (char c in "xyzw") curves.Add(Curve(path, "m_LocalRotation." + c, (0f, c == 'w' ? 1f : 0f), (1 / 3f, c == 'w' ? 1f : 0f)));
                    foreach (char c in "xyz") curves.Add(Curve(path, "localEulerAnglesRaw." + c, (0f, 0f), (1 / 3f, 0f)));
                    break;
                default:
                    foreach (char c in "xyz") curves.Add(Curve(path, kind + "." + c, (0f, 0f), (1 / 3f, 0f)));
                    break;
            }

            KeyFillPlan plan = KeyFill.Plan("clip", curves, 1 / 3.0, Fps);
            AssertRefused(() => KeyFill.KeyPoses(plan, curves, clip.Rig, clip.BonePaths, clip.ScenePose()), "curves", problem);
        }

        [Test]
        public void AWeightedSegmentToReadBetweenKeysIsRefused()
        {
            KeyedClipFixture clip = KeyedClipFixture.Create(new[] { 0, 10 }, euler: false);
            var curves = new List<KeyedCurve>(clip.Curves);
            // A key on the root's height at frame 5: every other pose curve is read there, between its keys.
            int y = curves.FindIndex(c => c.Property == "m_LocalPosition.y");
            var keys = new List<CurveKey>(curves[y].Keys);
            keys.Insert(1, new CurveKey(5 / 30f, keys[0].Value, 0, 0));
            curves[y] = new KeyedCurve(curves[y].Path, curves[y].Property, keys);
            int x = curves.FindIndex(c => c.Path == clip.BonePaths[3] && c.Property == "m_LocalRotation.x");
            KeyedCurve bone = curves[x];
            curves[x] = new KeyedCurve(bone.Path, bone.Property, new[]
            {
                new CurveKey(bone.Keys[0].Time, bone.Keys[0].Value, 0, 0, 0.5f, 0.5f, 3),
                new CurveKey(bone.Keys[1].Time, bone.Keys[1].Value, 0, 0, 0.5f, 0.5f, 3),
            });
            KeyFillPlan plan = KeyFill.Plan("clip", curves, 1 / 3.0, Fps);
            AssertRefused(() => KeyFill.KeyPoses(plan, curves, clip.Rig, clip.BonePaths, clip.ScenePose()), "curves", "has no key at 0.1667 s and a weighted segment there");
        }

        [Test]
        public void HumanoidFillKeepsTheKeysAndWritesTheRecordedFrames()
        {
            string[] muscles = { "Spine Front-Back" };
            var set = new HashSet<string> { "Spine Front-Back" };
            var keyed = new CurveKey(0.5f, 0.25f, 1.5f, -2f, 0.2f, 0.4f, 3, KeyedClipFixture.ClampedAuto);
            var curves = new List<KeyedCurve>
            {
                new KeyedCurve("", "Spine Front-Back", new[] { new CurveKey(0f, 0f, 0f, 0f), keyed }),
                Curve("", "RootQ.x", (0f, 0f), (0.5f, 0f)),
                Curve("", "RootQ.y", (0f, 0f), (0.5f, 0f)),
                Curve("", "RootQ.z", (0f, 0f), (0.5f, 0f)),
                Curve("", "RootQ.w", (0f, -1f), (0.5f, -1f)), // the identity as −q: the recording holds +q
                Curve("", "Speed", (0f, 3f), (0.5f, 4f)), // an Animator parameter: no pose
            };
            KeyFillPlan plan = KeyFill.Plan("clip", curves, 0.5, Fps, null, set);
            Assert.That(plan.Kind, Is.EqualTo(KeyFillClipKind.Humanoid));
            int frames = 16;
            var positions = new float[3 * frames];
            var rotations = new float[4 * frames];
            var values = new float[frames];
            for (int f = 0; f < frames; f++)
            {
                rotations[4 * f + 3] = 1;
                values[f] = 0.01f * f;
            }

            IReadOnlyList<ClipCurve> recorded = HumanoidCurves.Build(muscles, 1 / Fps, positions, rotations, values);
            KeyFillEdit edit = KeyFill.Edit(plan, curves, recorded);
            IReadOnlyList<KeyedCurve> after = edit.Apply(curves);
            Assert.That(after[0].Keys.Count, Is.EqualTo(16));
            Assert.That(after[0].Keys[0], Is.EqualTo(curves[0].Keys[0]));
            Assert.That(after[0].Keys[15], Is.EqualTo(keyed), "the animator's key: every field kept");
            for (int f = 1; f < 15; f++) Assert.That(after[0].Keys[f].Value, Is.EqualTo(0.01f * f), "the recorded muscle value");
            for (int f = 1; f < 15; f++) Assert.That(after[4].Keys[f].Value, Is.EqualTo(-1f), "RootQ.w in the keys' hemisphere, not the recording's");
            Assert.That(after[5], Is.SameAs(curves[5]), "a parameter curve is not touched");
            AssertRefused(() => KeyFill.Edit(plan, curves, new List<ClipCurve>(recorded).GetRange(0, 7)), "curves", "the recording of the filled frames has no such curve");
        }
    }
}
