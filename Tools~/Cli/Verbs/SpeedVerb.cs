using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text.Json;
using System.Text.Json.Nodes;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.OnnxRuntime;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween speed</c>: how long the runtime takes per request, measured carefully (warm-up, many
    /// repetitions, median and p95), and with <c>--pytorch</c> the same request in PyTorch eager on the
    /// same machine and thread count, for the same architecture and for the paper's.
    /// </summary>
    public sealed class SpeedVerb : ICliVerb
    {
        private static readonly int[] Lengths = { 5, 15, 30 };
        private const int PastFrames = 10;

        private readonly ModelOptions _model = new ModelOptions(
            "speed",
            "The exported model (NAME.onnx; NAME.keys.onnx and NAME.frame.onnx beside it time lazy decoding). Default: the shipped " + ShippedModels.Default + ".",
            "Intra-op threads, for ONNX Runtime and (with --pytorch) torch alike.",
            1,
            "1 or more (the same count is given to torch)");

        private readonly Option<bool> _pytorch = new Option<bool>("--pytorch")
        {
            Description = "Also time the same request in PyTorch eager (python3 -m deltainterp.speed; same architecture, random weights, and the paper preset) in this run.",
        };

        private readonly Option<int> _repeats = new Option<int>("--repeats")
        {
            Description = "Timed repetitions per measurement (after a warm-up); fewer when a measurement exceeds its time budget.",
            HelpName = "N",
            DefaultValueFactory = _ => 500,
        };

        /// <summary>The largest crowd the benchmark builds (4 × the issue's largest measured crowd).</summary>
        private const int MaxCharacters = 1024;

        private readonly Option<int> _characters = new Option<int>("--characters")
        {
            Description = "characters of the crowd benchmark (all request a transition in the same frame; the JSON's \"crowd\" object); 0 skips it",
            DefaultValueFactory = _ => 64,
        };

        private readonly Option<string> _json = new Option<string>("--json")
        {
            Description = "Where to write the results: {\"model\", \"threads\", \"transition_ms\": {\"5\",\"15\",\"30\"}, \"network_ms\", \"lazy_frame_ms\", \"slerp_fk_us\", \"alloc_bytes_per_transition\", \"pytorch_transition_ms\", \"speedup_vs_pytorch\", \"paper_pytorch_transition_ms\"}; each time is {\"median\", \"p95\", \"samples\"}.",
            HelpName = "OUT",
            Required = true,
        };

        private readonly OutputOptions _output = new OutputOptions();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "speed",
                "Time the in-betweening runtime per request (P = 10 past keys, n = 5/15/30 missing frames):\n" +
                "  transition  the whole pipeline: localize, key features, network, SLERP + deltas, decode, un-localize, FK\n" +
                "  network     the ONNX Runtime run alone\n" +
                "  lazy frame  one frame decoded lazily after the keys were encoded (n = 30)\n" +
                "  slerp+fk    the SLERP baseline and FK alone (µs)\n" +
                "  allocation  managed bytes allocated per transition in steady state\n" +
                "Each is the median and 95th percentile of many runs after a warm-up. With --pytorch the same request\n" +
                "is timed in PyTorch eager on the same thread count (same architecture, and the paper's 1024-wide preset).\n" +
                OutputOptions.HelpText + "\n" +
                "Example:\n  inbetween speed --model Tests/Fixtures/tiny-model.onnx --threads 1 --pytorch --json out/speed.json");
            command.Options.Add(_model.Model);
            command.Options.Add(_model.Threads);
            command.Options.Add(_pytorch);
            command.Options.Add(_repeats);
            command.Options.Add(_json);
            command.Options.Add(_characters);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            OnnxRuntimeOptions options = _model.RuntimeOptions(parse);
            int threads = options.IntraOpThreads;
            int repeats = parse.GetValue(_repeats);
            string jsonPath = parse.GetValue(_json)!;
            if (repeats < 10) throw new CliErrors.UsageException($"inbetween speed: --repeats {repeats}; expected at least 10");
            string? root = RepositoryRoot();
            string? given = parse.GetValue(_model.Model);
            string modelPath = given ?? (root == null ? ShippedModels.Find(ShippedModels.Default) : Path.Combine(root, ShippedModels.Default));
            if (given == null && !File.Exists(modelPath))
            {
                throw new CliErrors.UsageException($"{modelPath}: the shipped model is not there; expected it after export (python3 -m deltainterp export), or pass --model FILE.onnx");
            }

            InputFile.Check(modelPath, "an exported model NAME.onnx (see Documentation~/model-contract.md)");
            // The output is checked before the minutes of measuring, not after.
            _output.Check(parse, jsonPath, new[] { modelPath, OnnxRuntimeInbetweener.LazyPath(modelPath, "keys"), OnnxRuntimeInbetweener.LazyPath(modelPath, "frame") });

            using Inbetweener model = OnnxRuntimeInbetweener.Load(modelPath, options);
            ModelContract contract = model.Contract;
            var results = new JsonObject
            {
                ["model"] = modelPath,
                ["name"] = contract.Name,
                ["threads"] = threads,
                ["past_frames"] = PastFrames,
                ["onnxruntime"] = OnnxRuntimeBackend.RuntimeVersion,
                ["processors"] = Environment.ProcessorCount,
                ["repeats"] = repeats,
            };

            var transition = new JsonObject();
            var network = new JsonObject();
            var stats = new Dictionary<int, Timing>();
            AnsiConsole.MarkupLine(Markup.Escape($"Timing {Path.GetFileName(modelPath)} ({contract.Architecture.Width} wide, {contract.Architecture.Blocks} blocks, {contract.JointCount} joints) on {threads} thread(s)..."));
            foreach (int n in Lengths)
            {
                Transition t = SyntheticRequest(contract, n);
                var global = new double[n * contract.JointCount * 3];
                Timing timing = Measure(() => model.Inbetween(t, global), repeats, 1e3);
                stats[n] = timing;
                transition[Key(n)] = timing.ToJson();
                network[Key(n)] = MeasureNetwork(modelPath, options, contract, n, repeats).ToJson();
            }

            results["transition_ms"] = transition;
            results["network_ms"] = network;

            if (model.SupportsLazyDecoding)
            {
                Transition t = SyntheticRequest(contract, 30);
                LazyDecoder lazy = model.CreateLazy(PastFrames, 30);
                results["lazy_keys_ms"] = Measure(() => lazy.Begin(t), repeats, 1e3).ToJson();
                int k = 0;
                Timing frame = Measure(() => lazy.DecodeFrame(k = (k + 1) % 30), repeats, 1e3);
                results["lazy_frame_ms"] = frame.ToJson();
                results["lazy_frame_fraction_of_transition_30"] = frame.Median / stats[30].Median;
            }
            else
            {
                results["lazy_frame_ms"] = null;
                AnsiConsole.MarkupLine(Markup.Escape($"lazy decoding not timed: {OnnxRuntimeInbetweener.LazyPath(modelPath, "keys")} / .frame.onnx not found beside the model"));
            }

            {
                Transition t = SyntheticRequest(contract, 30);
                var slerp = new SlerpBaseline();
                var positions = new double[30 * contract.JointCount * 3];
                var rotations = new double[30 * contract.JointCount * 4];
                results["slerp_fk_us"] = Measure(() =>
                {
                    slerp.Inbetween(t);
                    ForwardKinematics.Compute(t.Skeleton, 30, t.RootPositions, t.LocalRotations, positions, rotations);
                }, repeats * 4, 1e6).ToJson();
            }

            results["alloc_bytes_per_transition"] = AllocatedBytesPerTransition(model, contract, 1000);

            JsonObject? pytorch = null;
            if (parse.GetValue(_pytorch))
            {
                pytorch = RunPyTorch(root, contract, threads, repeats);
                results["pytorch"] = new JsonObject { ["torch"] = pytorch["torch"]?.DeepClone(), ["parameters"] = pytorch["parameters"]?.DeepClone(), ["paper_parameters"] = pytorch["paper_parameters"]?.DeepClone() };
                results["pytorch_transition_ms"] = pytorch["transition_ms"]!.DeepClone();
                var speedup = new JsonObject();
                foreach (int n in Lengths)
                {
                    double torchMs = pytorch["transition_ms"]![Key(n)]!["median"]!.GetValue<double>();
                    speedup[Key(n)] = torchMs / stats[n].Median;
                }

                results["speedup_vs_pytorch"] = speedup;
                results["paper_pytorch_transition_ms"] = pytorch["paper_transition_ms"]?.DeepClone();
            }
            else
            {
                results["pytorch_transition_ms"] = null;
                results["speedup_vs_pytorch"] = null;
                results["paper_pytorch_transition_ms"] = null;
            }

            int characters = parse.GetValue(_characters);
            // Bounded: each character holds its poses, history and decoder buffers (100,000 ran out of memory).
            if (characters < 0 || characters > MaxCharacters) throw new CliErrors.UsageException($"inbetween speed: --characters {characters}; expected 0 (skip) to {MaxCharacters}");
            if (characters > 0 && model.SupportsLazyDecoding)
            {
                AnsiConsole.MarkupLine(Markup.Escape($"Crowd: {characters} characters requesting a transition in the same frame..."));
                JsonObject crowd = CrowdBenchmark.Run(modelPath, options, characters);
                results["crowd"] = crowd;
                AnsiConsole.MarkupLine(Markup.Escape("crowd: " + crowd.ToJsonString()));
            }

            OutputFile.WriteAllText(jsonPath, results.ToJsonString(new JsonSerializerOptions { WriteIndented = true }));
            PrintSummary(results, pytorch != null);
            AnsiConsole.MarkupLine(Markup.Escape($"results written to {jsonPath}"));
            return 0;
        }

        /// <summary>Median, 95th percentile and sample count of repeated timings.</summary>
        private readonly struct Timing
        {
            public Timing(double median, double p95, int samples)
            {
                Median = median;
                P95 = p95;
                Samples = samples;
            }

            public double Median { get; }
            public double P95 { get; }
            public int Samples { get; }

            public JsonObject ToJson() => new JsonObject { ["median"] = Math.Round(Median, 6), ["p95"] = Math.Round(P95, 6), ["samples"] = Samples };
        }

        /// <summary>
        /// Warm-up (a tenth of the repeats, at least 20 runs and 0.2 s), then up to
        /// <paramref name="repeats"/> timed runs within a 10 s budget (at least 10).
        /// </summary>
        private static Timing Measure(Action action, int repeats, double unitsPerSecond)
        {
            var warm = Stopwatch.StartNew();
            for (int i = 0; i < Math.Max(20, repeats / 10) || warm.Elapsed.TotalSeconds < 0.2; i++) action();
            var samples = new double[repeats];
            int count = 0;
            var budget = Stopwatch.StartNew();
            while (count < repeats && (count < 10 || budget.Elapsed.TotalSeconds < 10))
            {
                long start = Stopwatch.GetTimestamp();
                action();
                samples[count++] = (Stopwatch.GetTimestamp() - start) * unitsPerSecond / Stopwatch.Frequency;
            }

            Array.Sort(samples, 0, count);
            double median = count % 2 == 1 ? samples[count / 2] : 0.5 * (samples[count / 2 - 1] + samples[count / 2]);
            double p95 = samples[Math.Min(count - 1, (int)Math.Ceiling(0.95 * count) - 1)];
            return new Timing(median, p95, count);
        }

        /// <summary>The ONNX Runtime run alone: a second session with the same options, inputs of one request.</summary>
        private static Timing MeasureNetwork(string path, OnnxRuntimeOptions options, ModelContract contract, int n, int repeats)
        {
            using OnnxRuntimeBackend backend = OnnxRuntimeBackend.Load(path, options);
            GraphTensors tensors = GraphTensors.Create(contract, ModelGraphKind.Whole, PastFrames, n, n);
            float[] features = tensors.KeyFeatures!.Floats!;
            var random = new Random(1);
            for (int i = 0; i < features.Length; i++) features[i] = (float)(0.2 * (random.NextDouble() - 0.5));
            using IInferenceBinding binding = tensors.Bind(backend);
            return Measure(binding.Run, repeats, 1e3);
        }

        private static double AllocatedBytesPerTransition(Inbetweener model, ModelContract contract, int calls)
        {
            Transition t = SyntheticRequest(contract, 30);
            var global = new double[30 * contract.JointCount * 3];
            for (int i = 0; i < 10; i++) model.Inbetween(t, global);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < calls; i++) model.Inbetween(t, global);
            return (GC.GetAllocatedBytesForCurrentThread() - before) / (double)calls;
        }

        /// <summary>
        /// A plausible request on the model's skeleton: the root walking along +X at hip height, small
        /// random joint rotations (timings do not depend on the values).
        /// </summary>
        private static Transition SyntheticRequest(ModelContract contract, int n)
        {
            var t = new Transition(contract.Skeleton, PastFrames, n);
            var random = new Random(n);
            int j = contract.JointCount;
            for (int k = 0; k < t.KeyFrameCount; k++)
            {
                int frame = k < PastFrames ? k : PastFrames + n;
                new Vector3D(2.0 * frame / contract.UnitScale * 0.01, 0.9 / contract.UnitScale, 0).Write(t.KeyRootPositions, 3 * k);
                for (int joint = 0; joint < j; joint++)
                {
                    var axis = new Vector3D(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                    QuaternionD q = Quaternions.FromAxisAngle((1.0 / Math.Max(axis.Length, 1e-9)) * axis, 0.4 * random.NextDouble());
                    q.Write(t.KeyLocalRotations, (k * j + joint) * 4);
                }
            }

            return t;
        }

        private static JsonObject RunPyTorch(string? root, ModelContract contract, int threads, int repeats)
        {
            if (root == null || !File.Exists(Path.Combine(root, "Training", "Python~", "deltainterp", "speed.py")))
            {
                throw new CliErrors.UsageException("inbetween speed: --pytorch needs the repository's Training/Python~/deltainterp (speed.py); expected to run from a checkout of the package");
            }

            string python = Environment.GetEnvironmentVariable("DELTAINTERP_PYTHON") ?? "/usr/bin/python3";
            string config = Path.Combine(Path.GetTempPath(), $"deltainterp-speed-{Environment.ProcessId}.json");
            string output = Path.Combine(Path.GetTempPath(), $"deltainterp-speed-{Environment.ProcessId}.out.json");
            OutputFile.WriteAllText(config, contract.DescriptionJson);
            try
            {
                AnsiConsole.MarkupLine(Markup.Escape($"Timing the same request in PyTorch eager ({python} -m deltainterp.speed, {threads} thread(s), then the paper preset)..."));
                var start = new ProcessStartInfo(python)
                {
                    WorkingDirectory = root,
                    UseShellExecute = false,
                    RedirectStandardError = true,
                };
                foreach (string a in new[] { "-m", "deltainterp.speed", "--config", config, "--threads", threads.ToString(CultureInfo.InvariantCulture), "--repeats", Math.Min(repeats, 200).ToString(CultureInfo.InvariantCulture), "--json", output })
                {
                    start.ArgumentList.Add(a);
                }

                start.Environment["PYTHONPATH"] = Path.Combine(root, "Training", "Python~");
                using Process? process = Process.Start(start);
                if (process == null) throw new CliErrors.UsageException($"inbetween speed: could not start {python}; expected Python 3 with torch (set DELTAINTERP_PYTHON)");
                string stderr = process.StandardError.ReadToEnd();
                process.WaitForExit();
                if (process.ExitCode != 0 || !File.Exists(output))
                {
                    string last = stderr.Trim().Split('\n')[^1];
                    throw new CliErrors.UsageException($"inbetween speed: {python} -m deltainterp.speed failed ({last}); expected Python 3 with torch and numpy (see Training/README)");
                }

                return JsonNode.Parse(File.ReadAllText(output))!.AsObject();
            }
            finally
            {
                File.Delete(config);
                File.Delete(output);
            }
        }

        private static void PrintSummary(JsonObject r, bool withPyTorch)
        {
            var table = new Table().Border(TableBorder.Rounded).Title($"[bold]speed[/] ({r["threads"]} thread(s); median / p95)");
            table.AddColumn("Measurement");
            foreach (int n in Lengths) table.AddColumn(new TableColumn("n = " + n).RightAligned());
            AddRow(table, "C# transition (ms)", r["transition_ms"]);
            AddRow(table, "C# network only (ms)", r["network_ms"]);
            if (withPyTorch)
            {
                AddRow(table, "PyTorch transition (ms)", r["pytorch_transition_ms"]);
                AddRow(table, "PyTorch, paper preset (ms)", r["paper_pytorch_transition_ms"]);
                var cells = new List<string> { "speed-up vs PyTorch (×)" };
                foreach (int n in Lengths) cells.Add(r["speedup_vs_pytorch"]![Key(n)]!.GetValue<double>().ToString("0.0", CultureInfo.InvariantCulture));
                table.AddRow(cells.ToArray());
            }

            AnsiConsole.Write(table);
            if (r["lazy_frame_ms"] is JsonObject lazy)
            {
                AnsiConsole.MarkupLine(Markup.Escape($"lazy: keys {Cell(r["lazy_keys_ms"])} ms, one frame {Cell(lazy)} ms = {r["lazy_frame_fraction_of_transition_30"]!.GetValue<double>():0.000} of a whole 30-frame transition"));
            }

            AnsiConsole.MarkupLine(Markup.Escape($"SLERP + FK alone (n = 30): {Cell(r["slerp_fk_us"])} µs; managed allocation per transition in steady state: {r["alloc_bytes_per_transition"]} bytes"));
        }

        private static void AddRow(Table table, string name, JsonNode? values)
        {
            var cells = new List<string> { name };
            foreach (int n in Lengths) cells.Add(Cell(values?[Key(n)]));
            table.AddRow(cells.ToArray());
        }

        private static string Cell(JsonNode? timing)
        {
            if (timing == null) return "-";
            double median = timing["median"]!.GetValue<double>(), p95 = timing["p95"]!.GetValue<double>();
            string format = median < 1 ? "0.000" : median < 100 ? "0.00" : "0.0";
            return median.ToString(format, CultureInfo.InvariantCulture) + " / " + p95.ToString(format, CultureInfo.InvariantCulture);
        }

        private static string Key(int n) => n.ToString(CultureInfo.InvariantCulture);

        /// <summary>The checkout this tool was built in (it lives under Tools~/.build), or null.</summary>
        private static string? RepositoryRoot()
        {
            foreach (string start in new[] { AppContext.BaseDirectory, Directory.GetCurrentDirectory() })
            {
                string? dir = start;
                while (dir != null)
                {
                    if (Directory.Exists(Path.Combine(dir, "Runtime", "Core")) && Directory.Exists(Path.Combine(dir, "Training")))
                    {
                        return dir;
                    }

                    dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
                }
            }

            return null;
        }
    }
}
