using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Baking;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Baking
{
    /// <summary>
    /// Issue 30: <see cref="KeyPlanner"/> (the CLI's --every and the editor baker's "every N") places keys by time:
    /// 0.5 s, 15 model frames and the input-frame count that equals them give the same keys on 30, 60 and 120 fps
    /// clips; no gap has fewer than the model's trained 5 missing model frames unless the clip is shorter.
    /// </summary>
    public sealed class KeyPlannerTests
    {
        private const double ModelFps = 30;
        private const int MinMissing = 5;

        [Test]
        public void SecondsModelFramesAndInputFramesGiveTheSameKeysAt30And60And120Fps()
        {
            foreach (double seconds in new[] { 10.0, 10.1, 10.13, 3.3, 2.0, 0.9, 17.77 })
            {
                double[]? times = null;
                foreach (int fps in new[] { 30, 60, 120 })
                {
                    int frames = (int)Math.Round(seconds * fps) + 1;
                    int[] bySeconds = KeyPlanner.Plan(KeySpacing.Parse("0.5s")!.Value, frames, 1.0 / fps, ModelFps, 0, MinMissing);
                    int[] byModel = KeyPlanner.Plan(KeySpacing.Parse("15mf")!.Value, frames, 1.0 / fps, ModelFps, 0, MinMissing);
                    int[] byInput = KeyPlanner.Plan(KeySpacing.Parse((fps / 2).ToString())!.Value, frames, 1.0 / fps, ModelFps, 0, MinMissing);
                    Assert.That(byModel, Is.EqualTo(bySeconds), $"{seconds} s at {fps} fps");
                    Assert.That(byInput, Is.EqualTo(bySeconds), $"{seconds} s at {fps} fps");
                    var t = new double[bySeconds.Length];
                    for (int i = 0; i < t.Length; i++) t[i] = bySeconds[i] / (double)fps;
                    if (times == null) times = t;
                    else Assert.That(t, Is.EqualTo(times).Within(1e-9), $"{seconds} s: key times at {fps} fps differ from 30 fps");
                }

                TestContext.WriteLine($"{seconds} s: keys at {string.Join(", ", times!)} s");
            }
        }

        [Test]
        public void NoGapHasFewerThanTheTrainedMissingFramesUnlessTheClipIsShorter()
        {
            int checkedLayouts = 0;
            // 30, 60 and 120 fps: whole input frames per model frame. (At 24 fps a 6-model-frame spacing is 4.8
            // input frames, so keys on whole frames can leave one missing frame fewer; not claimed here.)
            foreach (int fps in new[] { 30, 60, 120 })
            {
                foreach (string every in new[] { "6mf", "7mf", "10mf", "15mf", "20mf", "30mf", "39mf", "0.25s", "0.5s", "1s" })
                {
                    for (int frames = fps / 10 + 2; frames <= 6 * fps; frames++)
                    {
                        int first = frames > 10 ? 1 : 0;
                        int[] keys = KeyPlanner.Plan(KeySpacing.Parse(every)!.Value, frames, 1.0 / fps, ModelFps, first, MinMissing);
                        Assert.That(keys[0], Is.EqualTo(first));
                        Assert.That(keys[keys.Length - 1], Is.EqualTo(frames - 1), "the whole clip is baked");
                        double span = (frames - 1 - first) * ModelFps / fps;
                        for (int i = 1; i < keys.Length; i++)
                        {
                            int missing = (int)Math.Round((keys[i] - keys[i - 1]) * ModelFps / fps, MidpointRounding.AwayFromZero) - 1;
                            if (span >= MinMissing + 1) Assert.That(missing, Is.GreaterThanOrEqualTo(MinMissing), $"--every {every}, {frames} frames at {fps} fps: keys {string.Join(",", keys)}");
                            Assert.That(keys[i], Is.GreaterThan(keys[i - 1]));
                        }

                        checkedLayouts++;
                    }
                }
            }

            TestContext.WriteLine($"{checkedLayouts} layouts checked");
        }

        [Test]
        public void TheLastShortGapMovesOrMergesInsteadOfStayingTiny()
        {
            // 30 fps, a key every 15: 0, 15, …, 450 and the last frame 453 would leave a gap of 2 missing frames.
            int[] keys = KeyPlanner.Plan(new KeySpacing(15, KeySpacingUnit.InputFrames), 454, 1.0 / 30, ModelFps, 0, MinMissing);
            Assert.That(keys[keys.Length - 1], Is.EqualTo(453));
            Assert.That(keys[keys.Length - 2], Is.EqualTo(444), "435..453 split in the middle: 8 and 8 missing");
            // A key every 6: the last 6 + 2 frames cannot split into two gaps of 5 missing, so they merge.
            int[] six = KeyPlanner.Plan(new KeySpacing(6, KeySpacingUnit.InputFrames), 63, 1.0 / 30, ModelFps, 0, MinMissing);
            Assert.That(six[six.Length - 1] - six[six.Length - 2], Is.EqualTo(8));
        }

        [TestCase("0")]
        [TestCase("-5")]
        [TestCase("1.5")]
        [TestCase("1.5mf")]
        [TestCase("abc")]
        [TestCase("")]
        [TestCase("s")]
        [TestCase("0.5ss")]
        [TestCase("1e3s")]
        [TestCase("99999999999999999")]
        [TestCase("NaNs")]
        [TestCase("15 mf x")]
        public void HostileSpacingsDoNotParse(string text) => Assert.That(KeySpacing.Parse(text), Is.Null, text);

        [Test]
        public void SpacingsParseInTheirUnitsAndDescribeThemselvesInAllThree()
        {
            Assert.That(KeySpacing.Parse("60"), Is.EqualTo(new KeySpacing(60, KeySpacingUnit.InputFrames)));
            Assert.That(KeySpacing.Parse("60f"), Is.EqualTo(new KeySpacing(60, KeySpacingUnit.InputFrames)));
            Assert.That(KeySpacing.Parse("15mf"), Is.EqualTo(new KeySpacing(15, KeySpacingUnit.ModelFrames)));
            Assert.That(KeySpacing.Parse("0.5s"), Is.EqualTo(new KeySpacing(0.5, KeySpacingUnit.Seconds)));
            Assert.That(new KeySpacing(60, KeySpacingUnit.InputFrames).Describe(1.0 / 120, 30), Is.EqualTo("every 0.5 s = 15 model frames (at 30 fps) = 60 input frames (at 120 fps)"));
        }

        [Test]
        public void ASpacingBelowTwoModelFramesIsRefused()
        {
            var e = Assert.Throws<KeyLayoutException>(() => KeyPlanner.Plan(new KeySpacing(4, KeySpacingUnit.InputFrames), 500, 1.0 / 120, ModelFps, 0, MinMissing));
            Assert.That(e!.Message, Does.Contain("leaves no model frame to fill"));
        }

        [Test]
        public void TheEditorBakersClipKeysLieOnTheModelsTimelineAtTheSameTimesAsTheCliKeys()
        {
            // A 4 s mocap clip at 60 fps, a key every 0.5 s: the editor baker's keys (clip times → model frames).
            (int[] frames, double[] times) = KeyPlanner.PlanClip(new KeySpacing(0.5, KeySpacingUnit.Seconds), 4.0, 60, ModelFps, MinMissing);
            int[] cli = KeyPlanner.Plan(new KeySpacing(0.5, KeySpacingUnit.Seconds), 241, 1.0 / 60, ModelFps, 0, MinMissing);
            Assert.That(times, Is.EqualTo(Array.ConvertAll(cli, k => k / 60.0)).Within(1e-12));
            Assert.That(frames, Is.EqualTo(new[] { 0, 15, 30, 45, 60, 75, 90, 105, 120 }));
        }
    }
}
