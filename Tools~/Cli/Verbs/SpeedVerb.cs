using System.CommandLine;
using System.IO;
using System.Text.Json;
using System.Text.Json.Nodes;
using DeltaInterpolator.Cli.Presenters;
using DeltaInterpolator.Cli.Speed;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Evaluation.Speed;
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
                "Example:\n  inbetween speed --model Tests/Fixtures~/tiny-model.onnx --threads 1 --pytorch --json out/speed.json");
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
            // Checked before the minutes of measuring, as every other value.
            int characters = parse.GetValue(_characters);
            if (characters < 0 || characters > CrowdBenchmark.MaxCharacters) throw new CliErrors.UsageException($"inbetween speed: --characters {characters}; expected 0 (skip) to {CrowdBenchmark.MaxCharacters}");
            string? root = RepositoryCheckout.Find();
            string? given = parse.GetValue(_model.Model);
            string modelPath = given ?? ShippedModels.Find(ShippedModels.Default);
            if (given == null && !File.Exists(modelPath))
            {
                throw new CliErrors.UsageException($"{modelPath}: the shipped model is not there; expected it after export (python3 -m deltainterp export), or pass --model FILE.onnx");
            }

            InputFile.Check(modelPath, "an exported model NAME.onnx (see Documentation~/model-contract.md)");
            // The output is checked before the minutes of measuring, not after.
            _output.Check(parse, jsonPath, new[] { modelPath, OnnxRuntimeInbetweener.LazyPath(modelPath, "keys"), OnnxRuntimeInbetweener.LazyPath(modelPath, "frame") });

            using Inbetweener model = OnnxRuntimeInbetweener.Load(modelPath, options);
            ModelContract contract = model.Contract;
            AnsiConsole.MarkupLine(Markup.Escape($"Timing {Path.GetFileName(modelPath)} ({contract.Architecture.Width} wide, {contract.Architecture.Blocks} blocks, {contract.JointCount} joints) on {threads} thread(s)..."));
            SpeedResults speed = RuntimeSpeed.Measure(model, () => OnnxRuntimeBackend.Load(modelPath, options), repeats);
            if (speed.LazyFrame == null)
            {
                AnsiConsole.MarkupLine(Markup.Escape($"lazy decoding not timed: {OnnxRuntimeInbetweener.LazyPath(modelPath, "keys")} / .frame.onnx not found beside the model"));
            }

            JsonObject? pytorch = parse.GetValue(_pytorch) ? PyTorchSpeed.Run(root, contract, threads, repeats) : null;
            JsonObject? crowd = null;
            if (characters > 0 && model.SupportsLazyDecoding)
            {
                AnsiConsole.MarkupLine(Markup.Escape($"Crowd: {characters} characters requesting a transition in the same frame..."));
                crowd = SpeedJson.Crowd(CrowdBenchmark.Run(() => OnnxRuntimeInbetweener.Load(modelPath, options, requireLazy: true), characters));
                AnsiConsole.MarkupLine(Markup.Escape("crowd: " + crowd.ToJsonString()));
            }

            JsonObject results = SpeedJson.Results(modelPath, contract, threads, repeats, speed, pytorch, crowd);
            OutputFile.WriteAllText(jsonPath, results.ToJsonString(new JsonSerializerOptions { WriteIndented = true }));
            SpeedTable.Print(results, pytorch != null);
            AnsiConsole.MarkupLine(Markup.Escape($"results written to {jsonPath}"));
            return 0;
        }
    }
}
