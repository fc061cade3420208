using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Regression tests for the hostile-input review (issue 8): each case ran the real tool in process
    /// on hand-made files and broke its promise (exit 2, one line, nothing overwritten) before the fix.
    /// </summary>
    [NonParallelizable]
    public class CliHardeningTests
    {
        /// <summary>A LaFAN1-shaped data folder of synthetic walking clips: subject 5 for testing, subject 1 for statistics.</summary>
        private static string DataFolder(TempFolder temp, string name, string test, string? training = null)
        {
            temp.Write(name + "/walk_subject5.bvh", test);
            temp.Write(name + "/walk_subject1.bvh", training ?? CliHarness.WalkClip(130));
            return temp[name];
        }

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

        // 10. Escape sequences and control bytes from a file reached the terminal raw.
        [Test]
        public void ControlCharactersFromFilesAreEscapedAndLongNamesClipped()
        {
            using var temp = new TempFolder();
            string named = temp.Write("esc.bvh", CliHarness.WalkClip(3).Replace("JOINT Spine", "JOINT Sp\u001b[2Jine\u0007\u202e"));
            CliRun info = CliHarness.Run("info", named);
            CliHarness.AssertSuccess(info);
            // The table may wrap the name; each escape must be there and no raw control character.
            Assert.That(info.Stdout, Does.Contain("Sp\\x1b["));
            Assert.That(info.Stdout, Does.Contain("\\x07"));
            Assert.That(info.Stdout, Does.Contain("\\u202e"));

            string badNumber = temp.Write("escbad.bvh", CliHarness.WalkClip(3).Replace("OFFSET 0 10 0", "OFFSET 0 \u001b]0;title\u0007 0"));
            Assert.That(CliHarness.AssertOneErrorLine(CliHarness.Run("info", badNumber)), Does.Contain("\\x1b]0;title\\x07"));

            string twice = temp.Write("twice.bvh", CliHarness.WalkClip(3).Replace("ROOT Hips", "ROOT " + new string('N', 10_000_000)).Replace("JOINT Spine", "JOINT " + new string('N', 10_000_000)));
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("info", twice), "is used twice");
            Assert.That(line.Length, Is.LessThan(300), "a 10 MB name makes a short message");

            string escPath = temp.Write("a\u001b[2Jb/x.bvh", "not bvh");
            Assert.That(CliHarness.AssertOneErrorLine(CliHarness.Run("info", escPath)), Does.Contain("a\\x1b[2Jb"));
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
    }

    /// <summary>A stream that fails like a full disk after a number of bytes.</summary>
    internal sealed class StreamThatFills : Stream
    {
        private readonly Stream _inner;
        private long _left;

        public StreamThatFills(Stream inner, long bytes)
        {
            _inner = inner;
            _left = bytes;
        }

        public override bool CanRead => false;
        public override bool CanSeek => false;
        public override bool CanWrite => true;
        public override long Length => _inner.Length;
        public override long Position { get => _inner.Position; set => throw new NotSupportedException(); }
        public override void Flush() => _inner.Flush();
        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();

        public override void Write(byte[] buffer, int offset, int count)
        {
            int now = (int)Math.Min(count, _left);
            _inner.Write(buffer, offset, now);
            _left -= now;
            if (now < count) throw new IOException("No space left on device (simulated)");
        }

        public override void Write(ReadOnlySpan<byte> buffer)
        {
            byte[] copy = buffer.ToArray();
            Write(copy, 0, copy.Length);
        }
    }
}
