using System.Collections.Generic;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    /// <summary>How the fill reads curves between their keys and keeps key poses on curves that lack a key there.</summary>
    [TestFixture]
    public sealed class KeyFillCurveTests
    {
        [Test]
        public void CurvesAreReadAsUnityPlaysHermiteSegments()
        {
            var linear = new KeyedCurve("a", "m_LocalPosition.x", new[] { new CurveKey(0f, 1f, 2f, 2f), new CurveKey(1f, 3f, 2f, 2f) });
            Assert.That(linear.Evaluate(0.25), Is.EqualTo(1.5).Within(1e-12), "tangents on the chord: a straight line");
            var flat = new KeyedCurve("a", "m_LocalPosition.x", new[] { new CurveKey(0f, 0f, 0f, 0f), new CurveKey(2f, 1f, 0f, 0f) });
            Assert.That(flat.Evaluate(0.5), Is.EqualTo(0.15625).Within(1e-12), "flat tangents: the smoothstep 3s² − 2s³ at s = 1/4");
            Assert.That(flat.Evaluate(-1), Is.EqualTo(0), "the first value held before the keys");
            Assert.That(flat.Evaluate(3), Is.EqualTo(1), "the last value held after them");
            var stepped = new KeyedCurve("a", "m_LocalPosition.x", new[] { new CurveKey(0f, 0f, 0f, float.PositiveInfinity), new CurveKey(1f, 1f, 0f, 0f) });
            Assert.That(stepped.Evaluate(0.9), Is.EqualTo(0), "an infinite tangent holds the key's value (a stepped key)");
        }

        [Test]
        public void ACurveWithoutAKeyOnAnotherCurvesKeyFrameGetsItsOwnValueThere()
        {
            KeyedClipFixture clip = KeyedClipFixture.Create(new[] { 0, 10, 20 }, euler: false);
            var curves = new List<KeyedCurve>(clip.Curves);
            int x = curves.FindIndex(c => c.Path == clip.BonePaths[3] && c.Property == "m_LocalRotation.x");
            // Bone 3 keyed on frames 0 and 20 only (all four components), the other bones on 0, 10 and 20.
            for (int i = 0; i < curves.Count; i++)
            {
                if (curves[i].Path != clip.BonePaths[3]) continue;
                IReadOnlyList<CurveKey> k = curves[i].Keys;
                curves[i] = new KeyedCurve(curves[i].Path, curves[i].Property, new[] { k[0], k[2] });
            }

            KeyFillPlan plan = KeyFill.Plan("clip", curves, 20 / 30.0, 30);
            Assert.That(plan.KeyFrames, Is.EqualTo(new[] { 0, 10, 20 }));
            CharacterPoseTrack poses = KeyFill.KeyPoses(plan, curves, clip.Rig, clip.BonePaths, clip.ScenePose());
            IReadOnlyList<KeyedCurve> after = KeyFill.Edit(plan, curves, clip.Rig, clip.BonePaths, poses.Motion).Apply(curves);
            CurveKey at10 = after[x].Keys[10];
            Assert.That(at10.Time, Is.EqualTo(10 / 30f));
            Assert.That(at10.Value, Is.EqualTo((float)curves[x].Evaluate(10 / 30.0)), "the key pose the curve plays there, made a key");
            Assert.That(after[x].Keys[0], Is.EqualTo(curves[x].Keys[0]));
            Assert.That(after[x].Keys[20], Is.EqualTo(curves[x].Keys[1]));
        }
    }
}
