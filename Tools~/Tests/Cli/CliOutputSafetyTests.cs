using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Cli;
using DeltaInterpolator.Core.IO;
using NUnit.Framework;
using static DeltaInterpolator.Tests.Cli.CliTestFiles;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Outputs of the tool (issues 8, 16): checked before any work, never an input, an existing file replaced only
    /// with --force and never one that appeared meanwhile, written whole or not at all (a full disk, an interruption
    /// or a non-finite result leaves the old file byte-identical and no temporary file). Each case broke before its fix.
    /// </summary>
    [NonParallelizable]
    public class CliOutputSafetyTests
    {
        // 1. A NaN result: 1e308 motion values are finite, so the reader accepts them; L2P overflows.
        [Test]
        public void NonFiniteResultIsAnErrorAndLeavesTheJsonByteIdentical()
        {
            using var temp = new TempFolder();
            string data = DataFolder(temp, "big", CliHarness.WalkClip(130, hugeAtFrame: 70));
            string json = temp.Write("out.json", "{\"old\": true}\n");
            byte[] before = File.ReadAllBytes(json);

            CliRun run = CliHarness.Run("benchmark", "--data", data, "--json", json, "--force");
            CliHarness.AssertOneErrorLine(run, "not a finite number");
            Assert.That(File.ReadAllBytes(json), Is.EqualTo(before), "the old --json file must stay byte-identical");
            Assert.That(Directory.GetFiles(temp.Path), Has.Length.EqualTo(1), "no temporary file left beside the output");

            CliRun noJson = CliHarness.Run("benchmark", "--data", data);
            CliHarness.AssertOneErrorLine(noJson, "walk_subject5.bvh: ");
            Assert.That(noJson.Stdout, Does.Not.Contain("NaN"), "never a NaN in a table");
        }

        // 1 (the writer itself): the benchmark's JSON writer interrupted half-way (the disk fills up)
        // leaves the old file byte-identical and no temporary file behind.
        [Test]
        public void BenchmarkJsonWriterInterruptedHalfWayLeavesTheOldFile()
        {
            using var temp = new TempFolder();
            string json = temp.Write("out.json", "{\"old\": true}\n");
            byte[] before = File.ReadAllBytes(json);
            Core.Bvh.BvhAnimation clip = Core.Bvh.BvhReader.Parse(CliHarness.WalkClip(130), "walk_subject5.bvh");
            var options = new Evaluation.Benchmark.BenchmarkOptions { Lengths = new[] { 5, 15 } };
            Evaluation.Benchmark.BenchmarkStatistics stats = Evaluation.Benchmark.BenchmarkStatistics.ComputeFromTraining(new[] { clip }, options, 50, 20, "test");
            Evaluation.Benchmark.BenchmarkReport report = Evaluation.Benchmark.LafanBenchmark.Run(
                new[] { clip }, stats, new Core.Inbetweening.IInbetweener[] { new Core.Inbetweening.ZeroVelocityBaseline(), new Core.Inbetweening.SlerpBaseline() }, options);

            var e = Assert.Throws<IOException>(() => Core.IO.OutputFile.Write(json, s => DeltaInterpolator.Cli.Verbs.BenchmarkVerb.WriteJson(new StreamThatFills(s, 100), report, "stats")))!;
            Assert.That(e.Message, Does.Contain("simulated"));
            Assert.That(File.ReadAllBytes(json), Is.EqualTo(before));
            Assert.That(Directory.GetFiles(temp.Path), Has.Length.EqualTo(1), "no temporary file left");

            // The same writer, uninterrupted, replaces the file with the complete results.
            Core.IO.OutputFile.Write(json, s => DeltaInterpolator.Cli.Verbs.BenchmarkVerb.WriteJson(s, report, "stats"));
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            Assert.That(doc.RootElement.GetProperty("windows").GetInt32(), Is.EqualTo(2));
        }

        // 2. Outputs never replace inputs or each other, and existing outputs only with --force.
        [Test]
        public void OutputsNeverReplaceInputsOrExistingFilesWithoutForce()
        {
            using var temp = new TempFolder();
            string data = DataFolder(temp, "data", CliHarness.WalkClip(130));
            string stats = temp["stats.json"];
            CliHarness.AssertSuccess(CliHarness.Run("benchmark", "--data", data, "--save-stats", stats));
            byte[] statsBytes = File.ReadAllBytes(stats);

            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--stats", stats, "--json", stats, "--force"), "is also an input");
            Assert.That(File.ReadAllBytes(stats), Is.EqualTo(statsBytes), "--json naming the --stats file must not replace the statistics");

            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--stats", stats, "--json", temp.Path + "/spelled/../stats.json", "--force"), "is also an input");
            string link = temp["link.json"];
            File.CreateSymbolicLink(link, stats);
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--stats", stats, "--json", link, "--force"), "is also an input");
            Assert.That(File.ReadAllBytes(stats), Is.EqualTo(statsBytes), "a symbolic link to the statistics is the statistics");

            string x = temp["x.json"];
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--save-stats", x, "--json", x), "both name");
            Assert.That(File.Exists(x), Is.False);

            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--save-stats", stats), "already exists");
            Assert.That(File.ReadAllBytes(stats), Is.EqualTo(statsBytes));

            string json = temp.Write("results.json", "old");
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--stats", stats, "--json", json), "already exists");
            Assert.That(File.ReadAllText(json), Is.EqualTo("old"));
            CliHarness.AssertSuccess(CliHarness.Run("benchmark", "--data", data, "--stats", stats, "--json", json, "--force"));
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            foreach (JsonProperty method in doc.RootElement.GetProperty("results").EnumerateObject())
            {
                Assert.That(method.Value.GetProperty("l2p").GetProperty("5").GetDouble(), Is.GreaterThanOrEqualTo(0), method.Name);
            }

            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--save-stats", temp["s2.json"], "--stats", stats), "--save-stats");
        }

        // 12. speed measured for 8 s, then failed on the output path.
        [Test]
        public void SpeedChecksItsOutputBeforeMeasuring()
        {
            using var temp = new TempFolder();
            // A copy: a broken check must not be able to overwrite the repository's fixture.
            string model = temp["tiny-model.onnx"];
            File.Copy(Path.Combine(TestEnvironment.RepositoryRoot!, "Tests", "Fixtures~", "tiny-model.onnx"), model);
            string unwritable = Directory.Exists("/proc/self") ? "/proc/inbetween-speed.json" : Path.Combine(temp.Write("plain", "x"), "out.json");
            CliRun run = CliHarness.Run("speed", "--model", model, "--json", unwritable);
            CliHarness.AssertOneErrorLine(run, "expected a");
            Assert.That(run.Stdout, Does.Not.Contain("Timing"), "nothing measured before the output was checked");

            string existing = temp.Write("speed.json", "old");
            CliRun exists = CliHarness.Run("speed", "--model", model, "--json", existing);
            CliHarness.AssertOneErrorLine(exists, "already exists");
            Assert.That(exists.Stdout, Does.Not.Contain("Timing"));
            Assert.That(File.ReadAllText(existing), Is.EqualTo("old"));
            CliHarness.AssertOneErrorLine(CliHarness.Run("speed", "--model", model, "--json", model, "--force"), "is also an input");
        }

        // 1. The contact sheet's SVG fallback was checked only after the work, with --force, and not against
        // inputs or other outputs: it replaced an input and the page just written.
        [Test]
        public void TheSvgFallbackOfTheContactSheetNeverReplacesAnInputOrAnotherOutput()
        {
            using var temp = new TempFolder();
            string clip = temp.Write("clip.svg", CliHarness.WalkClip(10));
            byte[] before = File.ReadAllBytes(clip);
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", clip, "--out", temp["page.html"], "--png", temp["clip.png"], "--force"), "clip.svg");
            Assert.That(File.ReadAllBytes(clip), Is.EqualTo(before), "the input must stay byte-identical");

            string bvh = temp.Write("walk.bvh", CliHarness.WalkClip(10));
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", bvh, "--out", temp["page.svg"], "--png", temp["page.png"]), "page.svg");
            Assert.That(File.Exists(temp["page.svg"]), Is.False, "refused before the page was written");

            // An existing fallback SVG is refused up front without --force, whether or not Chromium is there.
            string old = temp.Write("sheet.svg", "old");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", bvh, "--out", temp["p2.html"], "--png", temp["sheet.png"]), "sheet.svg");
            Assert.That(File.ReadAllText(old), Is.EqualTo("old"));
            Assert.That(File.Exists(temp["p2.html"]), Is.False);
        }

        // 3. Two runs writing the same new path without --force both succeeded; the later silently replaced the other.
        [Test]
        public void ANewOutputThatAppearedMeanwhileIsNeverReplaced()
        {
            using var temp = new TempFolder();
            string path = temp["out.bvh"];
            OutputFile.Check(path, false);
            File.WriteAllText(path, "the other run's file"); // another run finished first
            var e = Assert.Throws<OutputPathException>(() => OutputFile.WriteAllText(path, "ours"))!;
            Assert.That(e.Message, Does.Contain("appeared while this command ran"));
            Assert.That(e.Message, Does.Contain("; expected"));
            Assert.That(File.ReadAllText(path), Is.EqualTo("the other run's file"));
            Assert.That(TemporaryFiles(temp.Path), Is.Empty, "no temporary file left");

            // With --force (checked as existing) the file is replaced, as asked.
            OutputFile.Check(path, true);
            OutputFile.WriteAllText(path, "ours");
            Assert.That(File.ReadAllText(path), Is.EqualTo("ours"));

            // A new path still missing at the end is created as before.
            string fresh = temp["fresh.bvh"];
            OutputFile.Check(fresh, false);
            OutputFile.WriteAllText(fresh, "new");
            Assert.That(File.ReadAllText(fresh), Is.EqualTo("new"));
        }

        // 4. NaN or infinity reached a written BVH with exit 0 (bake of a file with a 1e308 root value at a
        // key; retarget --scale 1e308 wrote Infinity).
        [Test]
        public void NonFiniteMotionIsNeverWritten()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("huge.bvh", CmuExcerpt(241, 120, "1e308"));
            string output = temp.Write("out.bvh", "good old output\n");
            CliRun bake = CliHarness.Run("bake", input, "--every", "40", "--out", output, "--force", "--model", Model);
            CliHarness.AssertOneErrorLine(bake, "huge.bvh: ");
            Assert.That(File.ReadAllText(output), Is.EqualTo("good old output\n"), "the old output must stay");
            Assert.That(TemporaryFiles(temp.Path), Is.Empty);

            string plain = temp.Write("plain.bvh", CmuExcerpt(121));
            string retargeted = temp["scaled.bvh"];
            CliRun scaled = CliHarness.Run("retarget", plain, "--to", "model", "--out", retargeted, "--scale", "1e308", "--model", Model);
            string line = CliHarness.AssertOneErrorLine(scaled, "not a finite number");
            Assert.That(File.Exists(retargeted), Is.False, line);

            // The writer itself refuses a NaN before a byte reaches the file.
            Core.Bvh.BvhAnimation walk = Core.Bvh.BvhReader.Parse(CliHarness.WalkClip(3), "walk.bvh");
            walk.Motion.LocalRotations[5] = double.NaN;
            string target = temp.Write("nan.bvh", "old");
            Assert.Throws<Core.DataFormatException>(() => Core.Bvh.BvhWriter.Write(walk, target));
            Assert.That(File.ReadAllText(target), Is.EqualTo("old"));
        }

        // 18. SIGTERM during a write left .NAME.XXXXXXXX.tmp files behind.
        [Test]
        public void AnInterruptedWriteLeavesNoTemporaryFile()
        {
            using var temp = new TempFolder();
            string path = temp.Write("out.bin", "old");
            var started = new System.Threading.ManualResetEventSlim();
            var release = new System.Threading.ManualResetEventSlim();
            var writer = System.Threading.Tasks.Task.Run(() =>
            {
                try
                {
                    OutputFile.Write(path, s =>
                    {
                        s.Write(new byte[1000], 0, 1000);
                        started.Set();
                        release.Wait();
                        throw new IOException("simulated end of the process");
                    });
                }
                catch (IOException)
                {
                }
            });
            Assert.That(started.Wait(TimeSpan.FromSeconds(30)), Is.True);
            Assert.That(TemporaryFiles(temp.Path), Has.Length.EqualTo(1), "the write is under way");
            OutputFile.DeleteTemporaries(); // what the SIGINT/SIGTERM handler does
            Assert.That(TemporaryFiles(temp.Path), Is.Empty);
            release.Set();
            writer.Wait();
            Assert.That(File.ReadAllText(path), Is.EqualTo("old"));
        }
    }
}
