using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Evaluation.Metrics;
using DeltaInterpolator.OnnxRuntime;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween benchmark</c>: the official LaFAN1 in-betweening benchmark on a folder of BVH files,
    /// for the zero-velocity and SLERP baselines (and, later, models), printed as the official tables
    /// and optionally written as JSON.
    /// </summary>
    public sealed class BenchmarkVerb : ICliVerb
    {
        private readonly Option<string> _data = new Option<string>("--data")
        {
            Description = "Folder with the LaFAN1 BVH files. Test windows come from *_subject5.bvh; without --stats, statistics are computed from *_subject1..4.bvh.",
            HelpName = "DIR",
            Required = true,
        };

        private readonly Option<string?> _stats = new Option<string?>("--stats")
        {
            Description = "Statistics JSON (x_mean, x_std, offsets), e.g. ../shared/data/lafan1/train_stats_official.json for the official L2P scale. Default: computed from the training files in --data (windows 50, offset 20).",
            HelpName = "FILE",
        };

        private readonly Option<int> _window = new Option<int>("--window")
        {
            Description = "Frames per test window.",
            HelpName = "FRAMES",
            DefaultValueFactory = _ => 65,
        };

        private readonly Option<int> _offset = new Option<int>("--offset")
        {
            Description = "Frames between test window starts.",
            HelpName = "FRAMES",
            DefaultValueFactory = _ => 40,
        };

        private readonly Option<string> _lengths = new Option<string>("--lengths")
        {
            Description = "Transition lengths (missing frames), comma-separated.",
            HelpName = "N,N,...",
            DefaultValueFactory = _ => "5,15,30,45",
        };

        private readonly Option<int> _pastFrames = new Option<int>("--past-frames")
        {
            Description = "Give the methods only the last P of the 10 context frames (network key indices 0..P-1, target P+n). Windows, facing frame and target stay the official ones, so Interp. and Zero-V (frame 9 and the target only) do not change.",
            HelpName = "P",
            DefaultValueFactory = _ => 10,
        };

        private readonly Option<string> _pastPolicy = new Option<string>("--past-policy")
        {
            Description = "With --past-frames below 10: 'feed' gives the P frames alone; 'repeat' repeats the earliest of them in front to fill 10 past keys (what a model trained at 10 past frames only knows).",
            HelpName = "feed|repeat",
            DefaultValueFactory = _ => "feed",
        };

        private readonly Option<string?> _json = new Option<string?>("--json")
        {
            Description = "Also write the results as JSON to this file: {\"windows\", \"window\", \"offset\", \"stats\", \"results\": {method: {l2q|l2p|npss: {length: value}}}}.",
            HelpName = "OUT",
        };

        private readonly ModelOptions _model = new ModelOptions(
            "benchmark",
            "Also score an exported model (NAME.onnx, contract of Documentation~/model-contract.md) as the \"model\" row, through the same Core in-betweener the Unity component uses (ONNX Runtime backend).",
            "ONNX Runtime intra-op threads for --model.",
            0,
            "0 (ONNX Runtime's choice) or more");

        private readonly Option<string?> _saveStats = new Option<string?>("--save-stats")
        {
            Description = "Save the statistics computed from the training files to this JSON file (reusable with --stats; not with --stats).",
            HelpName = "OUT",
        };

        private readonly OutputOptions _output = new OutputOptions();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "benchmark",
                "Run the official LaFAN1 in-betweening benchmark (Harvey et al. 2020) on the zero-velocity and SLERP baselines\n" +
                "and, with --model FILE.onnx, an exported Δ-Interpolator model (the \"model\" row).\n" +
                "Test windows of subject 5 are centred and turned to face +X at the last of 10 past frames; for each transition\n" +
                "length n the n frames after them are filled from frame 9 and the target frame 10+n, then scored:\n" +
                "  L2Q  mean distance of global quaternions (all joints' components at once)\n" +
                "  L2P  mean distance of global positions, each coordinate divided by the statistics' std\n" +
                "  NPSS power-spectrum distance of global quaternions (Gopalakrishnan et al. 2019)\n" +
                "Lower is better. A result that is not a finite number (motion values too large, e.g. 1e308) is an error (exit 2).\n" +
                OutputOptions.HelpText + "\n" +
                "Examples:\n" +
                "  inbetween benchmark --data ../shared/data/lafan1 --stats ../shared/data/lafan1/train_stats_official.json\n" +
                "  inbetween benchmark --data ../shared/data/lafan1 --stats ../shared/data/lafan1/train_stats_official.json \\\n" +
                "      --model Runtime/Models/DeltaInterpolator-LaFAN1.onnx --lengths 5,15,30 --past-frames 1 --past-policy repeat");
            command.Options.Add(_data);
            command.Options.Add(_stats);
            command.Options.Add(_window);
            command.Options.Add(_offset);
            command.Options.Add(_lengths);
            command.Options.Add(_pastFrames);
            command.Options.Add(_pastPolicy);
            command.Options.Add(_json);
            command.Options.Add(_saveStats);
            command.Options.Add(_model.Model);
            command.Options.Add(_model.Threads);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            string data = parse.GetValue(_data)!;
            string? statsPath = parse.GetValue(_stats);
            string? jsonPath = parse.GetValue(_json);
            string? saveStats = parse.GetValue(_saveStats);
            var options = new BenchmarkOptions
            {
                Window = parse.GetValue(_window),
                Offset = parse.GetValue(_offset),
                Lengths = ParseLengths(parse.GetValue(_lengths)!),
                FedPastFrames = parse.GetValue(_pastFrames),
                ShortContext = ParsePolicy(parse.GetValue(_pastPolicy)!),
            };
            if (options.FedPastFrames < 1 || options.FedPastFrames > options.PastFrames)
            {
                throw new CliErrors.UsageException($"inbetween benchmark: --past-frames {options.FedPastFrames}; expected 1..{options.PastFrames} (the last P of the {options.PastFrames} context frames)");
            }

            try
            {
                options.Validate();
            }
            catch (ArgumentException e)
            {
                throw new CliErrors.UsageException("inbetween benchmark: " + e.Message);
            }

            if (!Directory.Exists(data))
            {
                string what = File.Exists(data) ? "is a file, not a directory" : "no such directory";
                throw new CliErrors.UsageException($"{data}: {what}; expected the folder of LaFAN1 BVH files (e.g. ../shared/data/lafan1)");
            }

            IReadOnlyList<string> testFiles = LafanDataset.FindFiles(data, LafanDataset.TestSubjects);
            if (testFiles.Count == 0)
            {
                throw new CliErrors.UsageException($"{data}: no *_subject5.bvh files; expected the LaFAN1 test files (subject 5) in --data");
            }

            if (statsPath != null)
            {
                InputFile.Check(statsPath, "a statistics JSON such as train_stats_official.json");
                if (saveStats != null)
                {
                    throw new CliErrors.UsageException($"inbetween benchmark: --save-stats {saveStats} with --stats {statsPath}; expected one of them (--save-stats keeps statistics computed from the training files)");
                }
            }

            string? modelPath = parse.GetValue(_model.Model);
            if (modelPath != null) InputFile.Check(modelPath, "an exported model NAME.onnx (see Documentation~/model-contract.md)");
            OnnxRuntimeOptions runtimeOptions = _model.RuntimeOptions(parse);

            // Outputs are checked before any work: never an input, never an existing file without --force.
            IReadOnlyList<string> trainingFiles = LafanDataset.FindFiles(data, LafanDataset.TrainingSubjects);
            var inputs = new List<string?> { data, statsPath, modelPath };
            if (modelPath != null)
            {
                inputs.Add(OnnxRuntimeInbetweener.LazyPath(modelPath, "keys"));
                inputs.Add(OnnxRuntimeInbetweener.LazyPath(modelPath, "frame"));
            }

            inputs.AddRange(testFiles);
            inputs.AddRange(trainingFiles);
            if (jsonPath != null && saveStats != null && string.Equals(Path.GetFullPath(jsonPath), Path.GetFullPath(saveStats), StringComparison.Ordinal))
            {
                throw new CliErrors.UsageException($"inbetween benchmark: --json and --save-stats both name {jsonPath}; expected two different files");
            }

            if (jsonPath != null) _output.Check(parse, jsonPath, inputs.Concat(new[] { saveStats }));
            if (saveStats != null) _output.Check(parse, saveStats, inputs.Concat(new[] { jsonPath }));
            var methods = new List<IInbetweener> { new ZeroVelocityBaseline(), new SlerpBaseline() };
            using Inbetweener? model = modelPath == null ? null : OnnxRuntimeInbetweener.Load(modelPath, runtimeOptions);
            if (model != null)
            {
                model.DisplayName = "Model (" + Path.GetFileNameWithoutExtension(modelPath) + ")";
                methods.Add(model);
            }

            // Progress goes to stderr so stdout holds only the results; when stderr is not a terminal
            // (CI logs, pipes) the bars are skipped instead of leaving escape-code residue.
            IAnsiConsole progressConsole = AnsiConsole.Create(new AnsiConsoleSettings
            {
                Out = new AnsiConsoleOutput(Console.Error),
                Interactive = Console.IsErrorRedirected ? InteractionSupport.No : InteractionSupport.Detect,
            });
            var total = Stopwatch.StartNew();
            BenchmarkStatistics? statistics = null;
            BvhAnimation[]? testClips = null;
            BenchmarkReport? report = null;
            double readSeconds = 0, statsSeconds = 0, evalSeconds = 0;
            long testBytes = testFiles.Sum(f => new FileInfo(f).Length);
            int trainingFileCount = 0;

            progressConsole.Progress()
                .AutoClear(true)
                .HideCompleted(false)
                .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn(), new RemainingTimeColumn())
                .Start(ctx =>
                {
                    IProgress<BenchmarkProgress>? reporter = Console.IsErrorRedirected ? null : new SpectreProgress(ctx);
                    if (statsPath != null)
                    {
                        statistics = BenchmarkStatistics.Load(statsPath);
                    }
                    else
                    {
                        var sw = Stopwatch.StartNew();
                        if (trainingFiles.Count == 0)
                        {
                            throw new CliErrors.UsageException($"{data}: no *_subject1..4.bvh training files to compute statistics from; expected them in --data, or pass --stats FILE");
                        }

                        trainingFileCount = trainingFiles.Count;
                        BvhAnimation[] training = LafanDataset.ReadAll(trainingFiles, reporter, "Reading training files");
                        RequireWindows(training, new BenchmarkOptions { Window = 50, Offset = 20 }, data, "training files (subjects 1-4) for the statistics", "pass --stats FILE");
                        statistics = BenchmarkStatistics.ComputeFromTraining(
                            training, options, 50, 20,
                            $"computed from {training.Length} training files in {data} (subjects 1-4, windows 50/20)", reporter);
                        statsSeconds = sw.Elapsed.TotalSeconds;
                    }

                    var read = Stopwatch.StartNew();
                    testClips = LafanDataset.ReadAll(testFiles, reporter, "Reading test files");
                    readSeconds = read.Elapsed.TotalSeconds;
                    RequireWindows(testClips, options, data, "test files (subject 5)", "a shorter --window");
                    // Refuse a model for another skeleton before evaluating anything.
                    model?.Contract.CheckSkeleton(testClips[0].Skeleton, testFiles[0]);
                    var eval = Stopwatch.StartNew();
                    report = LafanBenchmark.Run(testClips, statistics, methods, options, reporter);
                    evalSeconds = eval.Elapsed.TotalSeconds;
                });

            RequireFinite(report!, data);
            if (saveStats != null)
            {
                RequireFinite(statistics!, data);
                OutputFile.WriteAllText(saveStats, statistics!.ToJson());
            }

            PrintTables(report!);
            int frames = testClips!.Sum(c => c.Motion.FrameCount);
            string statsLine = statsPath != null
                ? $"statistics: {statsPath}"
                : $"statistics: computed from {trainingFileCount} training files in {statsSeconds:0.00} s{(saveStats != null ? ", saved to " + saveStats : "")}";
            statsPath = statsPath == null ? null : TerminalText.Safe(statsPath, TerminalText.LineLength);
            AnsiConsole.MarkupLine(Markup.Escape(
                $"{report!.WindowCount} windows of {options.Window} frames every {options.Offset} from {testClips!.Length} test files ({frames:N0} frames); {statsLine}"));
            if (options.EffectivePastFrames != options.PastFrames)
            {
                string layout = options.ShortContext == ShortContextPolicy.RepeatEarliest
                    ? $"repeated to {options.KeyPastFrames} past keys (--past-policy repeat)"
                    : $"fed alone as {options.KeyPastFrames} past keys (--past-policy feed)";
                AnsiConsole.MarkupLine(Markup.Escape($"past frames: the last {options.EffectivePastFrames} of {options.PastFrames}, {layout}"));
            }

            AnsiConsole.MarkupLine(Markup.Escape(
                $"read {testBytes / 1e6:0.0} MB in {readSeconds:0.000} s ({testBytes / 1e6 / Math.Max(readSeconds, 1e-9):0} MB/s), evaluated in {evalSeconds:0.000} s, total {total.Elapsed.TotalSeconds:0.00} s"));

            if (jsonPath != null)
            {
                WriteJson(jsonPath, report, statistics!.Source);
                AnsiConsole.MarkupLine(Markup.Escape($"results written to {jsonPath}"));
            }

            return 0;
        }

        /// <summary>Refuses clips that hold no window (user input, not a bug: short files or a huge --window).</summary>
        private static void RequireWindows(IReadOnlyList<BvhAnimation> clips, BenchmarkOptions options, string data, string what, string remedy)
        {
            if (LafanBenchmark.CountWindows(clips, options) > 0) return;
            int longest = clips.Count == 0 ? 0 : clips.Max(c => c.Motion.FrameCount);
            throw new CliErrors.UsageException(
                $"{data}: the {clips.Count} {what} are shorter than one window of {options.Window} frames (the longest has {longest:N0} frames; a window needs more than {options.Window}); expected longer files or {remedy}");
        }

        /// <summary>Refuses a report with a value that is not a finite number: never a NaN in a table or a file.</summary>
        private static void RequireFinite(BenchmarkReport report, string data)
        {
            for (int m = 0; m < report.MethodIds.Count; m++)
            {
                foreach (int n in report.Lengths)
                {
                    MetricTotals t = report.Get(report.MethodIds[m], n);
                    foreach ((string metric, double value) in new[] { ("L2Q", t.L2Q), ("L2P", t.L2P), ("NPSS", t.Npss) })
                    {
                        if (!double.IsFinite(value))
                        {
                            throw new CliErrors.UsageException(
                                $"{data}: {report.MethodNames[m]} {metric} at length {n} is {value.ToString(CultureInfo.InvariantCulture)}; expected finite results (motion values small enough for the metrics, e.g. |value| < 1e100)");
                        }
                    }
                }
            }
        }

        /// <summary>Refuses statistics that are not finite before they are saved.</summary>
        private static void RequireFinite(BenchmarkStatistics statistics, string data)
        {
            foreach (double[] values in new[] { statistics.Mean, statistics.StandardDeviation, statistics.Offsets })
            {
                foreach (double v in values)
                {
                    if (!double.IsFinite(v))
                    {
                        throw new CliErrors.UsageException($"{data}: the statistics computed from the training files hold {v.ToString(CultureInfo.InvariantCulture)}; expected finite motion values in the training files");
                    }
                }
            }
        }

        private static ShortContextPolicy ParsePolicy(string text)
        {
            switch (text)
            {
                case "feed": return ShortContextPolicy.FeedAvailable;
                case "repeat": return ShortContextPolicy.RepeatEarliest;
                default: throw new CliErrors.UsageException($"inbetween benchmark: --past-policy '{text}'; expected feed or repeat");
            }
        }

        private static IReadOnlyList<int> ParseLengths(string text)
        {
            var lengths = new List<int>();
            foreach (string part in text.Split(','))
            {
                if (!int.TryParse(part.Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out int n) || n < 1)
                {
                    throw new CliErrors.UsageException($"inbetween benchmark: --lengths '{text}' has '{part.Trim()}'; expected comma-separated whole numbers ≥ 1 such as 5,15,30,45");
                }

                lengths.Add(n);
            }

            return lengths;
        }

        private static void PrintTables(BenchmarkReport report)
        {
            PrintTable(report, "L2Q", "global quaternion error", t => t.L2Q, "0.0000");
            PrintTable(report, "L2P", "global position error", t => t.L2P, "0.0000");
            PrintTable(report, "NPSS", "power spectrum distance", t => t.Npss, "0.00000");
            AnsiConsole.MarkupLine("Lower is better. Lengths are missing frames; Interp. = SLERP + root LERP, Zero-V = last past pose held.");
        }

        private static void PrintTable(BenchmarkReport report, string metric, string meaning, Func<MetricTotals, double> value, string format)
        {
            var table = new Table().Border(TableBorder.Rounded)
                .Title($"[bold]{metric}[/] ({Markup.Escape(meaning)})");
            table.AddColumn(new TableColumn("Lengths"));
            foreach (int n in report.Lengths) table.AddColumn(new TableColumn(n.ToString(CultureInfo.InvariantCulture)).RightAligned());
            for (int m = 0; m < report.MethodIds.Count; m++)
            {
                var cells = new List<string> { Markup.Escape(report.MethodNames[m]) };
                foreach (int n in report.Lengths)
                {
                    cells.Add(value(report.Get(report.MethodIds[m], n)).ToString(format, CultureInfo.InvariantCulture));
                }

                table.AddRow(cells.ToArray());
            }

            AnsiConsole.Write(table);
        }

        private static void WriteJson(string path, BenchmarkReport report, string statsSource)
        {
            OutputFile.Write(path, stream => WriteJson(stream, report, statsSource));
        }

        /// <summary>The results as JSON (a throw half-way leaves the target untouched: see <see cref="OutputFile.Write"/>).</summary>
        internal static void WriteJson(Stream stream, BenchmarkReport report, string statsSource)
        {
            using var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true });
            w.WriteStartObject();
            w.WriteNumber("windows", report.WindowCount);
            w.WriteNumber("window", report.Window);
            w.WriteNumber("offset", report.Offset);
            w.WriteString("stats", statsSource);
            w.WriteNumber("past_frames", report.FedPastFrames);
            w.WriteString("past_policy", report.ShortContext == ShortContextPolicy.RepeatEarliest ? "repeat" : "feed");
            w.WriteStartObject("results");
            for (int m = 0; m < report.MethodIds.Count; m++)
            {
                string id = report.MethodIds[m];
                w.WriteStartObject(id);
                WriteMetric(w, report, id, "l2q", t => t.L2Q);
                WriteMetric(w, report, id, "l2p", t => t.L2P);
                WriteMetric(w, report, id, "npss", t => t.Npss);
                w.WriteEndObject();
            }

            w.WriteEndObject();
            w.WriteEndObject();
        }

        private static void WriteMetric(Utf8JsonWriter w, BenchmarkReport report, string id, string name, Func<MetricTotals, double> value)
        {
            w.WriteStartObject(name);
            foreach (int n in report.Lengths) w.WriteNumber(n.ToString(CultureInfo.InvariantCulture), value(report.Get(id, n)));
            w.WriteEndObject();
        }
    }
}
