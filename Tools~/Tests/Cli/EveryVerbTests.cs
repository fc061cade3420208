using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text.Json;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>Issue 30: <c>--every</c> in input frames (bare), model frames (<c>mf</c>) or seconds (<c>s</c>) on <c>bake</c> and <c>score</c>; hostile values refused in one line.</summary>
    public sealed class EveryVerbTests
    {
        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        private static int[] BakedKeys(TempFolder dir, string file, string every, string spacing)
        {
            string name = Path.GetFileNameWithoutExtension(file) + "-" + every;
            string json = dir["keys-" + name + ".json"];
            CliRun run = CliHarness.Run("bake", file, "--every", every, "--reference-frame", "0", "--feet", "off", "--out", dir["out-" + name + ".bvh"], "--json", json);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain(spacing), "the spacing in all three units");
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            JsonElement keys = doc.RootElement.GetProperty("keys");
            var result = new int[keys.GetArrayLength()];
            for (int i = 0; i < result.Length; i++) result[i] = keys[i].GetInt32();
            return result;
        }

        /// <summary>
        /// The 120 fps sample's first <paramref name="seconds"/> at 120 / <paramref name="step"/> fps: every
        /// <paramref name="step"/>-th frame, the frame time that many times longer.
        /// </summary>
        private static string AtRate(TempFolder dir, int step, double seconds)
        {
            string[] lines = File.ReadAllLines(Sample);
            int frameTime = Array.FindIndex(lines, l => l.StartsWith("Frame Time:", StringComparison.Ordinal));
            var text = new List<string>(lines[..(frameTime - 1)]);
            var frames = new List<string>();
            int last = frameTime + 1 + (int)Math.Round(seconds * 120);
            for (int i = frameTime + 1; i <= last && i < lines.Length; i += step) if (lines[i].Trim().Length > 0) frames.Add(lines[i]);
            text.Add("Frames: " + frames.Count.ToString(CultureInfo.InvariantCulture));
            text.Add("Frame Time: " + (step / 120.0).ToString("0.0000000", CultureInfo.InvariantCulture));
            text.AddRange(frames);
            string path = dir[$"walk-{120 / step}fps.bvh"];
            File.WriteAllLines(path, text);
            return path;
        }

        /// <summary>
        /// The same walk at 120, 60 and 30 fps (the bundled 120 fps clip's first 9.1 s, and every 2nd and 4th frame of
        /// it): --every 0.5s, 15mf and the input-frame count that equals them (60, 30, 15) bake the same keys in each
        /// file, the keys fall at the same times in all three files, and no gap holds fewer than the model's trained 5
        /// missing model frames — 9.1 s is no whole number of half seconds, so the last 0.1 s must move or merge a key
        /// (baked from frame 0, the one instant every rate shares).
        /// </summary>
        [Test]
        public void SecondsModelFramesAndInputFramesBakeTheSameKeysAt30And60And120Fps()
        {
            if (!File.Exists(Sample)) Assert.Ignore($"{Sample} absent; skipping.");
            using var dir = new TempFolder();
            double[]? times = null;
            foreach (int fps in new[] { 120, 60, 30 })
            {
                string file = AtRate(dir, 120 / fps, 9.1);
                string spacing = $"keys every 0.5 s = 15 model frames (at 30 fps) = {fps / 2} input frames (at {fps} fps)";
                int[] input = BakedKeys(dir, file, (fps / 2).ToString(CultureInfo.InvariantCulture), spacing);
                Assert.That(BakedKeys(dir, file, "15mf", spacing), Is.EqualTo(input), $"{fps} fps");
                Assert.That(BakedKeys(dir, file, "0.5s", spacing), Is.EqualTo(input), $"{fps} fps");
                var t = new double[input.Length];
                for (int i = 0; i < t.Length; i++) t[i] = input[i] / (double)fps;
                for (int i = 1; i < input.Length; i++)
                {
                    int missing = (int)Math.Round((input[i] - input[i - 1]) * 30.0 / fps) - 1;
                    Assert.That(missing, Is.GreaterThanOrEqualTo(5), $"{fps} fps: keys {string.Join(",", input)}");
                }

                if (times == null) times = t;
                else Assert.That(t, Is.EqualTo(times).Within(1e-3), $"{fps} fps: key times differ from those at 120 fps");
                TestContext.WriteLine($"{fps} fps: {input.Length} keys: {string.Join(",", input)}");
            }
        }

        [TestCase("0")]
        [TestCase("-15")]
        [TestCase("1.5")]
        [TestCase("abc")]
        [TestCase("0.5ss")]
        [TestCase("\u001b[2J", TestName = "{m}(ESC[2J)")] // a raw ESC in the name: filtered runs (--filter) would skip the case
        [TestCase("99999999999999999999")]
        public void HostileSpacingsAreRefusedInOneLine(string every)
        {
            using var dir = new TempFolder();
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", Sample, "--every", every, "--out", dir["out.bvh"]), "--every");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", dir.Path, "--every", every), "--every");
            Assert.That(File.Exists(dir["out.bvh"]), Is.False);
        }

        [Test]
        public void ASpacingBelowTwoModelFramesIsRefusedNamingTheFile()
        {
            if (!File.Exists(Sample)) Assert.Ignore($"{Sample} absent; skipping.");
            using var dir = new TempFolder();
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", Sample, "--every", "1mf", "--out", dir["out.bvh"]), "leaves no model frame to fill");
        }
    }
}
