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
    /// Bad input to the tool (issues 8, 16): deep, short, huge or degenerate files, named pipes, long command lines,
    /// unbounded thread counts, bad maps and options are one line `FILE:LINE: what; expected` with exit 2, in bounded
    /// time and memory, naming what the path is. Each case broke before its fix.
    /// </summary>
    [NonParallelizable]
    public class CliBadInputTests
    {
        // 3. Deep nesting: 80,000 joints (6 MB) aborted info and benchmark with a stack overflow.
        [Test]
        public void DeepNestingNeverOverflowsTheStack()
        {
            using var temp = new TempFolder();
            string deep = temp.Write("deep.bvh", CliHarness.DeepChain(80000));
            CliRun info = CliHarness.Run("info", deep);
            CliHarness.AssertSuccess(info);
            Assert.That(info.Stdout, Does.Contain("80000 joints"));
            Assert.That(info.Stdout, Does.Contain("(the first 1,000 of 80,000 joints are listed)"));

            string data = DataFolder(temp, "deepdata", CliHarness.DeepChain(80000));
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data), "shorter than one window");
        }

        // 6. Test files shorter than one window are user input, not a bug.
        [TestCase("zero frames", 0, null)]
        [TestCase("10 frames", 10, null)]
        [TestCase("huge --window", 130, "100000000")]
        public void TestFilesShorterThanOneWindowAreBadInput(string what, int frames, string? window)
        {
            using var temp = new TempFolder();
            string data = DataFolder(temp, "short", CliHarness.WalkClip(frames));
            CliRun run = window == null ? CliHarness.Run("benchmark", "--data", data) : CliHarness.Run("benchmark", "--data", data, "--window", window);
            CliHarness.AssertOneErrorLine(run, "shorter than one window");

            string trainingShort = DataFolder(temp, "training", CliHarness.WalkClip(130), CliHarness.WalkClip(20));
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", trainingShort), "training files");
        }

        // 7. info in proportion to its input: a 5,000-deep file and a 10 MB joint name.
        [Test]
        public void InfoOnDeepFilesAndHugeNamesStaysSmall()
        {
            using var temp = new TempFolder();
            string deep = temp.Write("deep5000.bvh", CliHarness.DeepChain(5000));
            string name = temp.Write("name.bvh", CliHarness.WalkClip(3).Replace("JOINT Spine", "JOINT " + new string('S', 10_000_000)));
            foreach (string file in new[] { deep, name })
            {
                var clock = Stopwatch.StartNew();
                CliRun run = CliHarness.Run("info", file);
                double seconds = clock.Elapsed.TotalSeconds;
                CliHarness.AssertSuccess(run);
                TestContext.Progress.WriteLine($"info {Path.GetFileName(file)} ({new FileInfo(file).Length:N0} bytes): {seconds:0.00} s, {run.Stdout.Length:N0} characters of output");
                // Before: a table 10,000 columns wide (19.6 s, 1.6 GB) or a 10 MB cell (34.7 s, 3.2 GB).
                Assert.That(run.Stdout.Length, Is.LessThan(400_000), "output in proportion to what is shown, not to the nesting or name length");
                Assert.That(run.Stdout.Split('\n').Max(l => l.Length), Is.LessThan(200), "no line wider than a terminal's few hundred columns");
                Assert.That(seconds, Is.LessThan(20), "generous bound for a shared machine; measured times are in the test output");
            }
        }

        // 8. A named pipe given as a file blocked forever.
        [Test]
        public void NamedPipesAreRefusedWithoutBlocking()
        {
            using var temp = new TempFolder();
            string fifo = CliHarness.MakeFifo(temp["pipe.bvh"]);
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "info", fifo), "named pipe");

            string data = DataFolder(temp, "data", CliHarness.WalkClip(130));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "benchmark", "--data", data, "--stats", fifo), "named pipe");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "benchmark", "--data", data, "--json", fifo, "--force"), "named pipe");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "benchmark", "--data", data, "--model", fifo), "named pipe");
            string pipeInData = CliHarness.MakeFifo(temp["data/run_subject5.bvh"]);
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "benchmark", "--data", data), "named pipe");
            Assert.That(pipeInData, Does.EndWith("run_subject5.bvh"));
        }

        // 9. --threads 1000 was accepted (80 s instead of 0.7 s).
        [Test]
        public void ThreadCountIsBoundedByTheProcessors()
        {
            using var temp = new TempFolder();
            string data = DataFolder(temp, "data", CliHarness.WalkClip(130));
            string model = Path.Combine(TestEnvironment.RepositoryRoot!, "Tests", "Fixtures~", "tiny-model.onnx");
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--model", model, "--threads", "1000"), "--threads 1000");
            Assert.That(line, Does.Contain(Environment.ProcessorCount.ToString(System.Globalization.CultureInfo.InvariantCulture)));
            CliHarness.AssertOneErrorLine(CliHarness.Run("speed", "--threads", "1000", "--json", temp["s.json"]), "--threads 1000");
        }

        // 11. Messages that misled: directory, unwritable output, model ":0:", CR-only line endings.
        [Test]
        public void MessagesNameWhatThePathIs()
        {
            using var temp = new TempFolder();
            CliHarness.AssertOneErrorLine(CliHarness.Run("info", temp.Path), "is a directory");
            CliHarness.AssertOneErrorLine(CliHarness.Run("info", temp["missing.bvh"]), "no such file");

            string data = DataFolder(temp, "data", CliHarness.WalkClip(130));
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--stats", data), "is a directory");
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", temp.Write("file.txt", "x")), "is a file, not a directory");
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--json", temp.Path), "is a directory");
            string unwritable = Directory.Exists("/proc/self") ? "/proc/inbetween-test.json" : Path.Combine(temp.Write("plain", "x"), "out.json");
            CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--json", unwritable), "expected a");

            string notModel = temp.Write("model.onnx", "this is not an ONNX model");
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("benchmark", "--data", data, "--model", notModel));
            Assert.That(line, Does.StartWith(notModel + ": "), "a whole-file problem says FILE: what; expected, without a made-up :0:");
            Assert.That(line, Does.Not.Contain(":0:"));

            string cr = temp.Write("cr.bvh", CliHarness.WalkClip(3).Replace("\n", "\r"));
            CliRun crInfo = CliHarness.Run("info", cr);
            CliHarness.AssertSuccess(crInfo);
            Assert.That(crInfo.Stdout, Does.Contain("Spine"));
            string crBad = temp.Write("crbad.bvh", CliHarness.WalkClip(3).Replace("OFFSET 0 10 0", "OFFSET 0 ten 0").Replace("\n", "\r"));
            CliHarness.AssertOneErrorLine(CliHarness.Run("info", crBad), "crbad.bvh:8: ");
        }

        // 9. A command line past ~40 KB aborted ONNX Runtime (exit 134); keys come from a file instead.
        [Test]
        public void LongCommandLinesAreRefusedAndKeysComeFromAFile()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("clip.bvh", CmuExcerpt(481));
            string keys = string.Join(",", Enumerable.Range(0, 8000).Select(k => k.ToString(CultureInfo.InvariantCulture)));
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--keys", keys, "--out", temp["o.bvh"], "--model", Model), "--keys @FILE");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "40", "--out", temp[new string('o', 40_000) + ".bvh"], "--model", Model), "command line");

            string list = temp.Write("keys.txt", "0, 40\n80 120\n160,200,240\n");
            CliRun fromFile = CliHarness.Run("bake", input, "--keys", "@" + list, "--out", temp["k.bvh"], "--model", Model, "--method", "slerp");
            CliHarness.AssertSuccess(fromFile);
            Assert.That(fromFile.Stdout, Does.Contain("7 keys"));
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--keys", "@" + temp.Path, "--out", temp["d.bvh"], "--model", Model), "is a directory");
        }

        // 11. Exit 1 "this is a bug" instead of exit 2.
        [TestCase("\u00a0")]
        [TestCase("\u2028")]
        public void BlankJointNamesAreBadInput(string name)
        {
            RequireShipped();
            using var temp = new TempFolder();
            string file = temp.Write("blank.bvh", CliHarness.WalkClip(10).Replace("JOINT Spine", "JOINT " + name));
            CliHarness.AssertOneErrorLine(CliHarness.Run("info", file), "blank.bvh:6: ");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", file, "--out", temp["p.html"]), "blank.bvh:6: ");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", file, "--every", "3", "--out", temp["b.bvh"], "--model", Model), "blank.bvh:6: ");
            CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", file, "--to", "model", "--out", temp["r.bvh"], "--model", Model), "blank.bvh:6: ");
        }

        [Test]
        public void PreviewOfAFileWithoutFramesIsBadInput()
        {
            using var temp = new TempFolder();
            string file = temp.Write("zero.bvh", CliHarness.WalkClip(0));
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", file, "--out", temp["z.html"]), "zero.bvh: has no frames");
            Assert.That(File.Exists(temp["z.html"]), Is.False);
        }

        [Test]
        public void BakePreviewOfMotionWithHugePositionsIsRefusedBeforeAnythingIsWritten()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("huge.bvh", CmuExcerpt(241, 30, "1e200"));
            CliRun run = CliHarness.Run("bake", input, "--every", "40", "--out", temp["o.bvh"], "--preview", temp["o.html"], "--model", Model);
            CliHarness.AssertOneErrorLine(run, "huge.bvh: ");
            Assert.That(File.Exists(temp["o.bvh"]), Is.False);
            Assert.That(File.Exists(temp["o.html"]), Is.False);
        }

        // 12. A 2-frame file with Frame Time: 1e5 ran past 60 s and gigabytes (retarget, bake); 1e6/1e9 threw.
        [TestCase("1e5")]
        [TestCase("1e9")]
        public void AHugeFrameTimeIsRefusedBeforeResampling(string frameTime)
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("slow.bvh", System.Text.RegularExpressions.Regex.Replace(CmuExcerpt(2), "Frame Time: .*", "Frame Time: " + frameTime));
            Assert.That(File.ReadAllText(input), Does.Contain("Frame Time: " + frameTime));
            var clock = Stopwatch.StartNew();
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "retarget", input, "--to", "model", "--out", temp["r.bvh"], "--model", Model), "frames × joints");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "bake", input, "--keys", "0,1", "--out", temp["b.bvh"], "--model", Model), "frames × joints");
            Assert.That(clock.Elapsed.TotalSeconds, Is.LessThan(30));
            Assert.That(TemporaryFiles(temp.Path), Is.Empty);
        }

        // 14. --map on a named pipe hung, on /dev/zero grew to gigabytes; 21. a folder was "no such file".
        [Test]
        public void MapsGoThroughTheSafeInputPath()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("clip.bvh", CmuExcerpt(121));
            string output = temp["o.bvh"];
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", temp.Path, "--model", Model), "is a directory");
            if (!OperatingSystem.IsWindows())
            {
                string fifo = CliHarness.MakeFifo(temp["map.json"]);
                CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", fifo, "--model", Model), "named pipe");
                CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", "/dev/zero", "--model", Model), "device");
            }

            string huge = temp.Write("huge.json", "{" + string.Concat(Enumerable.Range(0, 200_000).Select(i => $"\"junk{i}\": \"x\",")) + "\"Hips\": \"Hips\"}");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", huge, "--model", Model), "at most");
            Assert.That(File.Exists(output), Is.False);

            // 11: a blank key (or one of blank characters) is bad input naming the map.
            foreach (string key in new[] { "", " ", "\u00a0", "\u2028" })
            {
                string blank = temp.Write("blank.json", "{\"" + key + "\": \"Hips\"}");
                CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", input, "--to", "model", "--out", output, "--map", blank, "--model", Model), "blank.json:1: ");
            }

            // 21 for check: a folder is a folder.
            CliHarness.AssertOneErrorLine(CliHarness.Run("check", temp.Path), "is a directory");
        }

        // 19. A degenerate reference pose was reported under the map's name ("lafan1: …"), not the file.
        [Test]
        public void ADegenerateReferencePoseNamesTheFile()
        {
            RequireShipped();
            using var temp = new TempFolder();
            // Every offset zero: no leg length.
            string text = CmuExcerpt(10);
            string[] lines = text.Split('\n');
            for (int i = 0; i < lines.Length; i++)
            {
                if (lines[i].TrimStart().StartsWith("OFFSET", StringComparison.Ordinal)) lines[i] = "OFFSET 0 0 0";
            }

            string flat = temp.Write("flat.bvh", string.Join("\n", lines));
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", flat, "--to", "model", "--out", temp["o.bvh"], "--model", Model));
            Assert.That(line, Does.StartWith(flat + ": "), line);
        }

        // 20. Option errors printed System.Nullable`1[System.Int32].
        [Test]
        public void OptionErrorsSayTypesInWords()
        {
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("bake", "x.bvh", "--every", "abc", "--out", "o.bvh"), "a whole number");
            Assert.That(line, Does.Not.Contain("System."));
            line = CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", "x.bvh", "--to", "model", "--out", "o.bvh", "--scale", "big"), "a number");
            Assert.That(line, Does.Not.Contain("System."));
        }

        // 24. Unknown target joints in a --map were ignored without a word.
        [Test]
        public void UnknownTargetJointsInAMapAreNamedInAWarning()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("clip.bvh", CmuExcerpt(121));
            string map = temp.Write("map.json", "{\"Hipz\": \"Hips\", \"Tail\u001b[2J\": \"LowerBack\"}");
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--out", temp["o.bvh"], "--map", map, "--model", Model);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("warning:"));
            Assert.That(run.Stdout, Does.Contain("Hipz"));
            Assert.That(run.Stdout, Does.Contain("Tail\\x1b[2J"));
        }

        // 13. A model's training.fps of 1e6 passed check; retarget --model then resampled into millions of frames.
        [TestCase("1000000")]
        [TestCase("1e12")]
        [TestCase("0.001")]
        public void TheContractBoundsTheTrainingFrameRate(string fps)
        {
            var report = new Core.Inference.ModelCheckReport();
            string metadata = Tests.Inference.ModelContractTests.MetadataJson().Replace("\"fps\": 30", "\"fps\": " + fps);
            Assert.That(metadata, Does.Contain("\"fps\": " + fps));
            Core.Inference.ModelContract.Parse(metadata, "fast.onnx", report);
            Assert.That(report.HasErrors, Is.True, string.Join("\n", report.Select(c => c.Message)));
            Assert.That(report.Any(c => c.Message.Contains("training.fps")), Is.True);

            var fine = new Core.Inference.ModelCheckReport();
            Core.Inference.ModelContract.Parse(Tests.Inference.ModelContractTests.MetadataJson(), "ok.onnx", fine);
            Assert.That(fine.HasErrors, Is.False);
        }
    }
}
