using System;
using System.CommandLine;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.OnnxRuntime;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween check MODEL.onnx [--past P --gap N]</c>: every contract check of an exported model
    /// (the list the editor's model inspector shows), each with its severity and remedy, instead of the
    /// first problem only. Exit 2 when any is an error.
    /// </summary>
    public sealed class CheckVerb : ICliVerb
    {
        private readonly Argument<string> _model = new Argument<string>("MODEL")
        {
            Description = "An exported graph, e.g. Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx (NAME.keys.onnx and NAME.frame.onnx beside it are checked too).",
        };

        private readonly Option<int?> _past = new Option<int?>("--past")
        {
            Description = "Also check a request with P past key frames (default with --gap: the largest P the model was trained with).",
            HelpName = "P",
        };

        private readonly Option<int?> _gap = new Option<int?>("--gap")
        {
            Description = "Also check a request with a gap of N missing frames (default with --past: the longest gap the model was trained on).",
            HelpName = "N",
        };

        private readonly Option<string?> _skeleton = new Option<string?>("--skeleton")
        {
            Description = "Also check that the joints of this BVH file (names, parents, order) are the model's, as the motion fed to it must be.",
            HelpName = "FILE.bvh",
        };

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "check",
                "Check an exported model against this runtime: metadata and contract version, the graph's inputs and outputs,\n" +
                "the constant outputs of one probe run, the lazy graphs beside it, with --past/--gap a request shape against\n" +
                "the ranges the model was trained on, and with --skeleton a BVH file's joints against the model's.\n" +
                "Prints every result as Info, Warning or Error with what to do;\n" +
                "exit status 2 when any is an error (the model would be refused), 0 otherwise.\n" +
                "Examples:\n  inbetween check Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx --past 10 --gap 60\n" +
                "  inbetween check Tests/Fixtures~/tiny-model.onnx --skeleton ../shared/data/lafan1/walk4_subject1.bvh");
            command.Arguments.Add(_model);
            command.Options.Add(_past);
            command.Options.Add(_gap);
            command.Options.Add(_skeleton);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            string path = parse.GetValue(_model)!;
            int? past = parse.GetValue(_past);
            int? gap = parse.GetValue(_gap);
            string? skeleton = parse.GetValue(_skeleton);
            InputFile.Check(path, "an .onnx file exported by `python3 -m deltainterp export`");
            if (skeleton != null) InputFile.Check(skeleton, "a .bvh file");

            var report = new ModelCheckReport();
            ModelContract? contract = Check(path, report);
            if (contract != null && skeleton != null)
            {
                ModelChecks.Skeleton(contract, BvhReader.Read(skeleton).Skeleton, skeleton, report);
            }

            if (contract != null && (past.HasValue || gap.HasValue))
            {
                int p = past ?? (contract.HasTrainingRanges && contract.TrainingPastFrames.Max > 0 ? contract.TrainingPastFrames.Max : 10);
                int n = gap ?? (contract.HasTrainingRanges && contract.TrainingMissingFrames.Max > 0 ? contract.TrainingMissingFrames.Max : 30);
                ModelChecks.Request(contract, p, n, report);
                Describe(contract);
                AnsiConsole.MarkupLine(Markup.Escape($"Request checked: P = {p} past key frames, a gap of n = {n} frames."));
            }
            else if (contract != null)
            {
                Describe(contract);
            }

            Print(report);
            return report.HasErrors ? CliErrors.BadInput : 0;
        }

        /// <summary>The checks loading runs, collected: metadata (read by Core from the file's bytes), graph, probe, lazy graphs.</summary>
        private static ModelContract? Check(string path, ModelCheckReport report)
        {
            ModelGraphKind kind = path.EndsWith(".keys.onnx", StringComparison.OrdinalIgnoreCase) ? ModelGraphKind.Keys
                : path.EndsWith(".frame.onnx", StringComparison.OrdinalIgnoreCase) ? ModelGraphKind.Frame
                : ModelGraphKind.Whole;
            ModelContract? contract;
            try
            {
                using OnnxRuntimeBackend backend = OnnxRuntimeBackend.Load(path);
                contract = ModelChecks.Model(backend.Description, kind, report);
            }
            catch (DataFormatException e)
            {
                report.Error(e.Source, e.Problem, e.Expected);
                return null;
            }

            if (report.HasErrors || kind != ModelGraphKind.Whole) return contract;
            try
            {
                // Loading runs what the metadata cannot show: the probe (constant outputs) and the lazy graphs.
                using Inbetweener model = OnnxRuntimeInbetweener.Load(path);
                if (!model.SupportsLazyDecoding)
                {
                    report.Info(path, "NAME.keys.onnx and NAME.frame.onnx are not beside it", "lazy decoding (one frame at a time) needs them; python3 -m deltainterp export writes all three");
                }
            }
            catch (DataFormatException e)
            {
                report.Error(e.Source, e.Problem, e.Expected);
            }

            return contract;
        }

        private static void Describe(ModelContract c)
        {
            var table = new Table().Border(TableBorder.Rounded).HideHeaders();
            table.AddColumn("");
            table.AddColumn("");
            table.AddRow("Model", Markup.Escape(c.Name.Length > 0 ? TerminalText.Safe(c.Name, TerminalText.NameLength) : "(unnamed)"));
            table.AddRow("Graph", ModelContract.GraphName(c.Graph));
            table.AddRow("Contract version", string.Format(CultureInfo.InvariantCulture, "{0} (this runtime reads {1} to {2})", c.ContractVersion, ModelContract.MinSupportedVersion, ModelContract.MaxSupportedVersion));
            table.AddRow("Skeleton", string.Format(CultureInfo.InvariantCulture, "{0} joints, root '{1}'", c.JointCount, Markup.Escape(TerminalText.Safe(c.Skeleton.Names[0], TerminalText.NameLength))));
            table.AddRow("Unit scale", c.UnitScale.ToString("R", CultureInfo.InvariantCulture));
            table.AddRow("Delta modes", $"input {c.InputDeltaMode}, output {c.OutputDeltaMode}");
            table.AddRow("Largest P + n", c.LargestFrameIndex.ToString(CultureInfo.InvariantCulture));
            if (c.HasTrainingRanges)
            {
                table.AddRow("Trained on", string.Format(CultureInfo.InvariantCulture, "P = {0}..{1} past frames, gaps of {2}..{3} frames at {4:0.##} fps",
                    c.TrainingPastFrames.Min, c.TrainingPastFrames.Max, c.TrainingMissingFrames.Min, c.TrainingMissingFrames.Max, c.TrainingFps));
            }

            ModelArchitecture a = c.Architecture;
            table.AddRow("Network", string.Format(CultureInfo.InvariantCulture, "width {0}, {1} blocks, {2} heads, {3:N0} parameters", a.Width, a.Blocks, a.Heads, a.Parameters));
            AnsiConsole.Write(table);
        }

        private static void Print(ModelCheckReport report)
        {
            if (report.Count == 0)
            {
                AnsiConsole.MarkupLine("[green]OK[/]: no errors, warnings or notes.");
                return;
            }

            foreach (ModelCheck c in report)
            {
                string colour = c.Severity == CheckSeverity.Error ? "red" : c.Severity == CheckSeverity.Warning ? "yellow" : "blue";
                AnsiConsole.MarkupLine($"[{colour}]{c.Severity,-7}[/] {Markup.Escape(TerminalText.Safe(c.Source + ": " + c.Message, TerminalText.LineLength))}");
                if (c.Remedy.Length > 0) AnsiConsole.MarkupLine("        " + Markup.Escape(TerminalText.Safe(c.Remedy, TerminalText.LineLength)));
            }

            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture, "{0} error(s), {1} warning(s), {2} note(s).",
                report.CountOf(CheckSeverity.Error), report.CountOf(CheckSeverity.Warning), report.CountOf(CheckSeverity.Info))));
        }
    }
}
