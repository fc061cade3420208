using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.IO;
using System.Linq;
using DeltaInterpolator.Cli.Presenters;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Evaluation.Benchmark;
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
                "      --model Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx --lengths 5,15,30 --past-frames 1 --past-policy repeat");
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
            BenchmarkOptions options = BenchmarkLayoutArguments.Parse(
                parse.GetValue(_window), parse.GetValue(_offset), parse.GetValue(_lengths)!, parse.GetValue(_pastFrames), parse.GetValue(_pastPolicy)!);
            LafanBenchmarkFolder folder = LafanBenchmarkFolder.Open(data);
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
            var inputs = new List<string?> { data, statsPath, modelPath };
            if (modelPath != null)
            {
                inputs.Add(OnnxRuntimeInbetweener.LazyPath(modelPath, "keys"));
                inputs.Add(OnnxRuntimeInbetweener.LazyPath(modelPath, "frame"));
            }

            inputs.AddRange(folder.TestFiles.Concat(folder.TrainingFiles));
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

            var total = Stopwatch.StartNew();
            BenchmarkOutcome? outcome = null;
            ProgressBars.Run(progress => outcome = LafanBenchmarkRun.Execute(folder, statsPath, methods, options, progress));
            if (saveStats != null)
            {
                outcome!.RequireFiniteStatistics();
                OutputFile.WriteAllText(saveStats, outcome.Statistics.ToJson());
            }

            BenchmarkTables.Print(outcome!.Report);
            BenchmarkSummary.Print(outcome, options, statsPath, saveStats, total.Elapsed.TotalSeconds);
            if (jsonPath != null)
            {
                BenchmarkJson.Write(jsonPath, outcome.Report, outcome.Statistics.Source);
                AnsiConsole.MarkupLine(Markup.Escape($"results written to {jsonPath}"));
            }

            return 0;
        }

        /// <summary>The results as JSON: <see cref="BenchmarkJson"/> (the CLI tests write through the verb).</summary>
        internal static void WriteJson(Stream stream, BenchmarkReport report, string statsSource) => BenchmarkJson.Write(stream, report, statsSource);
    }
}
