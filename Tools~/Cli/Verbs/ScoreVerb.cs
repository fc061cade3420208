using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Text;
using DeltaInterpolator.Cli.Baking;
using DeltaInterpolator.Cli.Scoring;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.OnnxRuntime;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween score DATA... --every K --model A.onnx --model B.onnx</c>: bakes every file of folders (or
    /// data manifests) with each model and SLERP, as <c>bake</c> does, and prints per file, per subject group and
    /// in total the mean joint position error ÷ leg length and L2Q over every non-key frame, with each method's
    /// ratio to SLERP — so a user can compare models on their own motion.
    /// </summary>
    public sealed class ScoreVerb : ICliVerb
    {
        private readonly Argument<string[]> _data = new Argument<string[]>("DATA")
        {
            Description = "Folders of BVH files, or data manifests (.json, the format 'python3 -m deltainterp prepare' reads: per-file frame rate, frames to drop, reference frame, joint map)",
            Arity = ArgumentArity.OneOrMore,
        };

        private readonly Option<string> _every = new Option<string>("--every")
        {
            Description = "A key every K from each file's first usable frame, as bake --every: input frames by default (60), model frames with 'mf' (15mf) or seconds with 's' (0.5s).",
            HelpName = "K|Kmf|Xs",
            Required = true,
        };

        private readonly Option<string[]> _models = new Option<string[]>("--model")
        {
            Description = "Models to score (repeat the option); default: the shipped " + ShippedModels.Default + ".",
            HelpName = "FILE.onnx",
            AllowMultipleArgumentsPerToken = false,
        };

        private readonly Option<string[]> _only = new Option<string[]>("--only")
        {
            Description = "Score only files whose name or relative path matches one of these globs (e.g. '02_*').",
            HelpName = "GLOB",
            AllowMultipleArgumentsPerToken = true,
        };

        private readonly Option<string?> _json = new Option<string?>("--json")
        {
            Description = "Also write every file's scores and the totals as JSON.",
            HelpName = "OUT.json",
        };

        private readonly OutputOptions _output = new OutputOptions();

        private readonly Option<string> _up = UpAxisArgument.Create();
        private readonly Option<bool> _acceptReferencePose = ReferencePoseArgument.Create();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "score",
                "Bake every BVH file of folders (or data manifests) with each model and SLERP, keys every K frames, and score them:\n" +
                "per file, per subject group (the manifest's \"groups\") and in total over every non-key frame, the mean joint position\n" +
                "error ÷ the file's leg length and L2Q, with each method's ratio to SLERP (totals are ratios of sums over frames).\n" +
                "Example:\n  inbetween score Training/Python~/datasets/cmu.json Training/Python~/datasets/cmu-more.json --only '02_*' '09_*' '13_*' '38_*' --every 60 \\\n" +
                "      --model Runtime/Models/DeltaInterpolator-CMU.onnx --model Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx --json out/heldout.json");
            command.Arguments.Add(_data);
            command.Options.Add(_every);
            command.Options.Add(_models);
            command.Options.Add(_only);
            command.Options.Add(_json);
            _up.Description = UpAxisArgument.Help + " For files whose manifest names no \"up\".";
            command.Options.Add(_up);
            command.Options.Add(_acceptReferencePose);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            string[] data = parse.GetValue(_data) ?? Array.Empty<string>();
            KeySpacing every = EveryArgument.Parse(parse.GetValue(_every), "score")!.Value;
            Core.Retargeting.UpAxis up = UpAxisArgument.Parse(parse.GetValue(_up), "score");
            bool acceptReferencePose = parse.GetValue(_acceptReferencePose);
            var accepted = new List<string>();
            var models = new List<string>(parse.GetValue(_models) ?? Array.Empty<string>());
            if (models.Count == 0) models.Add(ShippedModels.Find(ShippedModels.Default));
            foreach (string m in models) Core.IO.InputFile.Check(m, "an exported model (NAME.onnx)");
            string[] only = parse.GetValue(_only) ?? Array.Empty<string>();
            foreach (string glob in only)
            {
                // Python's fnmatch reads a reversed range as empty (it matches nothing): on the command line that is
                // a typing slip, said now rather than as "no files".
                string? reversed = FileGlob.Parse(glob).ReversedRange;
                if (reversed != null) throw new CliErrors.UsageException($"inbetween score: --only '{glob}' has the reversed range {reversed}, which matches nothing; expected a range from low to high, e.g. [a-z]");
            }

            string? jsonPath = parse.GetValue(_json);
            var entries = new List<DataManifest.Entry>();
            var inputs = new List<string?>(models);
            foreach (string d in data)
            {
                DataManifest manifest = DataManifest.Open(d);
                entries.AddRange(manifest.Entries(only));
                // Settings files are inputs as much as the motion: the manifest (NAME.json or DIR/inbetween-data.json),
                // and a folder's manifest name even when it has none yet (a report written there would become one).
                inputs.Add(manifest.Path ?? Path.Combine(manifest.Folder, DataManifest.FileName));
            }

            if (entries.Count == 0) throw new CliErrors.UsageException($"{string.Join(", ", data)}: no BVH files to score; expected *.bvh files (check --only)");
            foreach (DataManifest.Entry e in entries)
            {
                inputs.Add(e.FilePath);
                inputs.Add(e.Map);
            }

            string? jsonFull = jsonPath == null ? null : OutputFile.Check(jsonPath, parse.GetValue(_output.Force), inputs.ToArray());

            var inbetweeners = new List<Inbetweener>();
            try
            {
                foreach (string m in models) inbetweeners.Add(InbetweenerLoader.Load(new OnnxModelFiles(m, new OnnxRuntimeOptions { IntraOpThreads = 1 }), LazyGraphs.None));
                var names = new List<string>();
                for (int i = 0; i < inbetweeners.Count; i++)
                {
                    // Two exports of one name (a new model against the shipped one) stay apart in the table and the JSON.
                    string name = inbetweeners[i].Contract.Name;
                    bool shared = inbetweeners.FindAll(other => other.Contract.Name == name).Count > 1;
                    names.Add(shared ? name + " (" + models[i] + ")" : name);
                }
                names.Add("SLERP");
                var sheet = new ScoreSheet(names);
                AnsiConsole.Progress().AutoClear(true).Start(ctx =>
                {
                    var task = ctx.AddTask("Baking files", maxValue: entries.Count);
                    foreach (DataManifest.Entry e in entries)
                    {
                        sheet.Add(ScoreFile(e, every, inbetweeners, up, acceptReferencePose, accepted));
                        task.Increment(1);
                    }
                });
                ScoreTable.Print(sheet, every);
                foreach (string line in accepted) AnsiConsole.MarkupLine(Markup.Escape("warning: " + line));
                if (jsonFull != null)
                {
                    string json = ScoreReport.Json(sheet, models, every, accepted);
                    OutputFile.Write(jsonFull, stream =>
                    {
                        using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
                        writer.Write(json);
                    });
                    AnsiConsole.MarkupLine(Markup.Escape("wrote " + jsonPath));
                }
            }
            finally
            {
                foreach (Inbetweener ib in inbetweeners) ib.Dispose();
            }

            return 0;
        }

        /// <summary>One file baked with every model (and SLERP once, with the first model's keys) and scored per leg length.</summary>
        private static ScoreRow ScoreFile(DataManifest.Entry e, KeySpacing every, List<Inbetweener> models, Core.Retargeting.UpAxis up, bool acceptReferencePose, List<string> accepted)
        {
            BvhAnimation animation = BakeInput.WithFrameRate(BvhReader.Read(e.FilePath), e.Fps);
            var position = new double[models.Count + 1];
            var l2q = new double[models.Count + 1];
            var skating = new double[models.Count + 1];
            int frames = 0, contacts = 0;
            double truthSkating = double.NaN;
            double leg = 0;
            for (int i = 0; i < models.Count; i++)
            {
                JointMap? map = BakeInput.LoadMap(e.Map, animation, models[i].Contract);
                int[] keys = BakeInput.Every(every, animation.Motion, e.FromFrame, models[i].Contract, e.FilePath);
                BakeMethod[] methods = i == 0 ? BakeInput.ModelAndSlerp(models[i], null, true, null) : new[] { BakeMethod.Model(models[i]) };
                BakeRun run = BakeInput.Bake(animation, e.FilePath, keys, models[i].Contract, methods, e.ReferenceFrame, map, quiet: true, up: e.Up ?? up, acceptReferencePose: acceptReferencePose || e.AcceptReferencePose);
                if (i == 0 && run.Rig is MappedRig mapped && mapped.AcceptedReference != null) accepted.Add($"{e.FilePath}: {mapped.AcceptedReference}");
                BakeScores scores = BakeScores.Measure(animation.Motion, run);
                leg = scores.LegLength;
                frames = scores["Model"].Accuracy.Frames;
                position[i] = scores["Model"].Accuracy.MeanPositionError / leg;
                l2q[i] = scores["Model"].Accuracy.L2Q;
                skating[i] = Skating(scores["Model"].Skating);
                if (i > 0) continue;
                position[models.Count] = scores["SLERP"].Accuracy.MeanPositionError / leg;
                l2q[models.Count] = scores["SLERP"].Accuracy.L2Q;
                skating[models.Count] = Skating(scores["SLERP"].Skating);
                contacts = scores.TruthSkating.ContactSamples;
                truthSkating = scores.TruthSkating.MeanSpeed;
            }

            try
            {
                return new ScoreRow(e.Name, e.Group, frames, leg, position, l2q, skating, contacts, truthSkating);
            }
            catch (ArgumentException)
            {
                throw new CliErrors.UsageException($"{e.FilePath}: non-finite errors; expected finite motion values");
            }
        }

        // No planted truth frame: nothing to weigh (the row's contact count is 0 then).
        private static double Skating(FootSkating s) => double.IsNaN(s.MeanSpeed) ? 0 : s.MeanSpeed;
    }
}
