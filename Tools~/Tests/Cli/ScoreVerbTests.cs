using System;
using System.Globalization;
using System.IO;
using System.Text.Json;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Tests.Retargeting;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// <c>bake --json</c>, <c>bake --every</c> near a clip's end, <c>--input-fps</c>, and <c>score</c> over a folder
    /// with a data manifest: the numbers users compare models with.
    /// </summary>
    public sealed class ScoreVerbTests
    {
        private string _dir = "";

        private static string Root => TestEnvironment.RepositoryRoot!;

        private static string Sample => Path.Combine(Root, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "inbetween-score-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveFolder() => Directory.Delete(_dir, true);

        [Test]
        public void EveryNeverRefusesItsOwnKeysWhenTheClipEndsJustAfterAKey()
        {
            // 07_08 has 363 frames: keys 0, 60, …, 360 and the last frame 362, closer than one model frame (4 input frames).
            string cmu = RetargetFixtures.RequireCmu();
            foreach (string file in new[] { "07_08.bvh", "06_09.bvh" })
            {
                string json = Path.Combine(_dir, file + ".json");
                CliRun run = CliHarness.Run("bake", Path.Combine(cmu, file), "--every", "60", "--reference-frame", "0", "--out", Path.Combine(_dir, file), "--json", json);
                CliHarness.AssertSuccess(run);
                using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
                JsonElement keys = doc.RootElement.GetProperty("keys");
                int last = keys[keys.GetArrayLength() - 1].GetInt32(), before = keys[keys.GetArrayLength() - 2].GetInt32();
                int frames = doc.RootElement.GetProperty("frames").GetInt32();
                Assert.That(last, Is.EqualTo(frames - 1), "the whole clip is baked");
                Assert.That(last - before, Is.GreaterThanOrEqualTo(5), "no two keys within one model frame");
            }
        }

        [Test]
        public void BakeJsonHoldsEachMethodsScoresPerLegLength()
        {
            string json = Path.Combine(_dir, "scores.json");
            CliRun run = CliHarness.Run("bake", Sample, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--out", Path.Combine(_dir, "out.bvh"), "--json", json);
            CliHarness.AssertSuccess(run);
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            JsonElement root = doc.RootElement;
            Assert.That(root.GetProperty("keys")[0].GetInt32(), Is.EqualTo(1), "--from-frame: the T-pose frame 0 is never a key");
            double leg = root.GetProperty("leg_length").GetDouble();
            Assert.That(leg, Is.InRange(14.0, 19.0), "CMU units: hip to toe about 15-17");
            int nonKey = root.GetProperty("non_key_frames").GetInt32();
            Assert.That(nonKey, Is.EqualTo(1140 - root.GetProperty("keys").GetArrayLength()), "frames 1..1140 less the keys");
            foreach (string method in new[] { "model", "slerp" })
            {
                JsonElement m = root.GetProperty("methods").GetProperty(method);
                double error = m.GetProperty("mean_position_error").GetDouble();
                Assert.That(m.GetProperty("mean_position_error_per_leg").GetDouble(), Is.EqualTo(error / leg).Within(1e-12));
                Assert.That(m.GetProperty("l2q").GetDouble(), Is.GreaterThan(0));
            }
        }

        [Test]
        public void InputFpsReadsTheClipAtItsTrueRate()
        {
            string output = Path.Combine(_dir, "at60.bvh");
            CliRun run = CliHarness.Run("bake", Sample, "--every", "30", "--reference-frame", "0", "--input-fps", "60", "--out", output);
            CliHarness.AssertSuccess(run);
            Assert.That(BvhReader.Read(output).Motion.FrameTime, Is.EqualTo(1.0 / 60).Within(1e-7), "BVH writes 0.01666667");
        }

        [Test]
        public void ScoreAddsUpEveryNonKeyFrameOfAFolder()
        {
            string data = Path.Combine(_dir, "data");
            Directory.CreateDirectory(Path.Combine(data, "nested"));
            File.Copy(Sample, Path.Combine(data, "01_01.bvh"));
            File.Copy(Sample, Path.Combine(data, "nested", "02_01.bvh"));
            File.WriteAllText(Path.Combine(data, "inbetween-data.json"),
                "{\"defaults\": {\"from_frame\": 1, \"reference_frame\": 0}, \"files\": {\"nested/*\": {\"from_frame\": 301}}, \"groups\": \"(\\\\d+)_\\\\d+\\\\.bvh$\"}");
            string json = Path.Combine(_dir, "score.json");
            CliRun run = CliHarness.Run("score", data, "--every", "60", "--json", json);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("subject 01").And.Contain("subject 02").And.Contain("all 2 files"));
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            JsonElement files = doc.RootElement.GetProperty("files");
            Assert.That(files.GetArrayLength(), Is.EqualTo(2));
            double sum = 0, sumSlerp = 0;
            int frames = 0;
            foreach (JsonElement f in files.EnumerateArray())
            {
                int n = f.GetProperty("non_key_frames").GetInt32();
                frames += n;
                JsonElement methods = f.GetProperty("methods");
                foreach (JsonProperty m in methods.EnumerateObject())
                {
                    if (m.Name == "slerp") sumSlerp += n * m.Value.GetProperty("position_per_leg").GetDouble();
                    else sum += n * m.Value.GetProperty("position_per_leg").GetDouble();
                }
            }

            Assert.That(files[1].GetProperty("non_key_frames").GetInt32(), Is.LessThan(files[0].GetProperty("non_key_frames").GetInt32()), "the nested file starts at frame 301");
            JsonElement total = doc.RootElement.GetProperty("total");
            Assert.That(total.GetProperty("non_key_frames").GetInt32(), Is.EqualTo(frames));
            foreach (JsonProperty m in total.GetProperty("methods").EnumerateObject())
            {
                double expected = (m.Name == "slerp" ? sumSlerp : sum) / frames;
                Assert.That(m.Value.GetProperty("position_per_leg").GetDouble(), Is.EqualTo(expected).Within(1e-12), m.Name);
            }
        }

        /// <summary>
        /// Issue 30: two models whose names share their first 17 characters, scored through a pipe (80 columns): each
        /// name is printed whole in the legend, never cut in a column header ("DeltaInterpola…").
        /// </summary>
        [Test]
        public void ScoreShowsWholeModelNamesAt80Columns()
        {
            string cmu = Path.Combine(Root, "Runtime", "Models", "DeltaInterpolator-CMU.onnx");
            string lafan1 = Path.Combine(Root, "Runtime", "Models", "DeltaInterpolator-LaFAN1.onnx");
            if (!File.Exists(cmu) || !File.Exists(lafan1)) Assert.Ignore("the shipped models are absent; skipping.");
            string data = Path.Combine(_dir, "data");
            Directory.CreateDirectory(data);
            File.Copy(Sample, Path.Combine(data, "09_12.bvh"));
            File.WriteAllText(Path.Combine(data, "inbetween-data.json"), "{\"defaults\": {\"from_frame\": 1, \"reference_frame\": 0}}");
            CliRun run = CliHarness.Run("score", data, "--every", "60", "--model", cmu, "--model", lafan1);
            CliHarness.AssertSuccess(run);
            string[] lines = run.Stdout.Split('\n');
            Assert.That(lines, Has.Some.Contains("[1] DeltaInterpolator-CMU"), run.Stdout);
            Assert.That(lines, Has.Some.Contains("[2] DeltaInterpolator-LaFAN1"), run.Stdout);
            Assert.That(run.Stdout, Does.Not.Contain("DeltaInterpola…"));
        }

        [Test]
        public void ScoreRefusesAnEmptySelectionAndAManifestWithUnknownFields()
        {
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", _dir, "--every", "60"), "no BVH files");
            string manifest = Path.Combine(_dir, "m.json");
            File.WriteAllText(manifest, "{\"folder\": \".\", \"default\": {}}");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", manifest, "--every", "60"), "unknown field");
        }
    
        [Test]
        public void ScoreAndBakeJsonTakeHostileInputsAsBadInput()
        {
            // A FIFO as the manifest and as a BVH file in the folder: refused at once, never read (no hang).
            string fifo = CliHarness.MakeFifo(Path.Combine(_dir, "m.json"));
            CliRun run = CliHarness.RunWithin(30, "score", fifo, "--every", "60");
            CliHarness.AssertOneErrorLine(run);
            string data = Path.Combine(_dir, "data");
            Directory.CreateDirectory(data);
            File.Copy(Sample, Path.Combine(data, "a.bvh"));
            CliHarness.MakeFifo(Path.Combine(data, "b.bvh"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "score", data, "--every", "60"), "b.bvh");
            File.Delete(Path.Combine(data, "b.bvh"));

            // A huge manifest is refused before it is read; a control character in a field name is printed escaped.
            string huge = Path.Combine(data, "inbetween-data.json");
            File.WriteAllText(huge, "{\"comment\": \"" + new string('x', 2 << 20) + "\"}");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "score", data, "--every", "60"), "bytes");
            File.WriteAllText(huge, "{\"\\u001b]0;pwned\\u0007\": 1}");
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("score", data, "--every", "60"), "unknown field");
            Assert.That(line.IndexOf((char)0x1b), Is.EqualTo(-1), "printed escaped (ordinal: culture-aware Contains ignores control characters)");
            File.Delete(huge);

            // --json: a folder, an input, the same path as --out.
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", data, "--every", "60", "--json", _dir));
            string input = Path.Combine(data, "a.bvh");
            byte[] before = File.ReadAllBytes(input);
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", data, "--every", "60", "--json", input, "--force"), "input");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "60", "--out", Path.Combine(_dir, "o.bvh"), "--json", input, "--force"), "input");
            string same = Path.Combine(_dir, "same.out");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "60", "--out", same, "--json", same), "same file");
            Assert.That(File.ReadAllBytes(input), Is.EqualTo(before), "no input was changed");

            // Non-finite motion in a scored file: refused, nothing written.
            string broken = Path.Combine(data, "a.bvh");
            File.WriteAllText(broken, File.ReadAllText(Sample).Replace("\n0.", "\n1e308 ", StringComparison.Ordinal));
            string json = Path.Combine(_dir, "scores.json");
            CliRun nonFinite = CliHarness.Run("score", data, "--every", "60", "--json", json);
            Assert.That(nonFinite.ExitCode, Is.EqualTo(2), nonFinite.ToString());
            Assert.That(File.Exists(json), Is.False);
        }

        [Test]
        public void SpeedCharactersTakesHostileValuesAsBadInput()
        {
            // A crowd too large to build is refused before any work (100,000 characters ran out of memory).
            string tiny = Path.Combine(Root, "Tests", "Fixtures~", "tiny-model.onnx");
            foreach (string value in new[] { "-1", "100000", "2147483647", "1e3" })
            {
                CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "speed", "--characters", value, "--model", tiny, "--json", Path.Combine(_dir, "s.json")));
            }

            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "speed", "--characters", "2", "--model", tiny, "--json", tiny, "--force"), "input");
            string fifo = CliHarness.MakeFifo(Path.Combine(_dir, "speed.json"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "speed", "--characters", "2", "--model", tiny, "--json", fifo));
        }

        [Test]
        public void BakeMapTakesHostileInputsAsBadInput()
        {
            // bake --map through the same safe input path as retarget --map: folder, FIFO, device, huge, a map that is the output.
            string output = Path.Combine(_dir, "o.bvh");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "bake", Sample, "--every", "60", "--out", output, "--map", _dir), "directory");
            string fifo = CliHarness.MakeFifo(Path.Combine(_dir, "map.json"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "bake", Sample, "--every", "60", "--out", output, "--map", fifo), "named pipe");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "bake", Sample, "--every", "60", "--out", output, "--map", "/dev/zero"), "device");
            string huge = Path.Combine(_dir, "huge.json");
            File.WriteAllText(huge, "{\"Hips\": \"" + new string('x', 2 << 20) + "\"}");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "bake", Sample, "--every", "60", "--out", output, "--map", huge), "at most");
            string map = Path.Combine(_dir, "real.json");
            File.WriteAllText(map, "{\"LeftToe\": null}");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", Sample, "--every", "60", "--out", map, "--map", map, "--force"), "input");
            Assert.That(File.ReadAllText(map), Is.EqualTo("{\"LeftToe\": null}"), "the map was not replaced");
            Assert.That(File.Exists(output), Is.False, "nothing written");
        }
}
}
