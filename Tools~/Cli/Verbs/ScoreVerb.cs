using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
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

        private readonly Option<int> _every = new Option<int>("--every")
        {
            Description = "A key every K input frames from each file's first usable frame (as bake --every).",
            HelpName = "K",
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

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "score",
                "Bake every BVH file of folders (or data manifests) with each model and SLERP, keys every K frames, and score them:\n" +
                "per file, per subject group (the manifest's \"groups\") and in total over every non-key frame, the mean joint position\n" +
                "error ÷ the file's leg length and L2Q, with each method's ratio to SLERP (totals are ratios of sums over frames).\n" +
                "Example:\n  inbetween score Training/Python~/datasets/cmu.json Training/Python~/datasets/cmu-more.json --only '02_*' '09_*' '13_*' '38_*' --every 60 \\\n" +
                "      --model Runtime/Models/DeltaInterpolator-CMU.onnx --model Runtime/Models/DeltaInterpolator-LaFAN1.onnx --json out/heldout.json");
            command.Arguments.Add(_data);
            command.Options.Add(_every);
            command.Options.Add(_models);
            command.Options.Add(_only);
            command.Options.Add(_json);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private sealed class Row
        {
            public string File = "";
            public string Group = "";
            public int Frames;
            public double Leg;
            public double[] Position = Array.Empty<double>(); // per method: mean error ÷ leg length
            public double[] L2Q = Array.Empty<double>();
        }

        private int Run(ParseResult parse)
        {
            string[] data = parse.GetValue(_data) ?? Array.Empty<string>();
            int every = parse.GetValue(_every);
            if (every < 1) throw new CliErrors.UsageException($"inbetween score: --every {every}; expected 1 or more frames");
            var models = new List<string>(parse.GetValue(_models) ?? Array.Empty<string>());
            if (models.Count == 0) models.Add(ShippedModels.Find(ShippedModels.Default));
            foreach (string m in models) Core.IO.InputFile.Check(m, "an exported model (NAME.onnx)");
            string[] only = parse.GetValue(_only) ?? Array.Empty<string>();
            string? jsonPath = parse.GetValue(_json);
            var manifests = new List<DataManifest>();
            foreach (string d in data) manifests.Add(DataManifest.Open(d));
            var entries = new List<DataManifest.Entry>();
            foreach (DataManifest m in manifests) entries.AddRange(m.Entries(only));
            if (entries.Count == 0) throw new CliErrors.UsageException($"{string.Join(", ", data)}: no BVH files to score; expected *.bvh files (check --only)");
            var inputs = new List<string?>(models);
            foreach (DataManifest.Entry e in entries) inputs.Add(e.FilePath);
            string? jsonFull = jsonPath == null ? null : OutputFile.Check(jsonPath, parse.GetValue(_output.Force), inputs.ToArray());

            var inbetweeners = new List<Inbetweener>();
            try
            {
                foreach (string m in models) inbetweeners.Add(new Inbetweener(OnnxRuntimeBackend.Load(m, new OnnxRuntimeOptions { IntraOpThreads = 1 })));
                var names = new List<string>();
                foreach (Inbetweener ib in inbetweeners) names.Add(ib.Contract.Name);
                names.Add("SLERP");
                var rows = new List<Row>();
                AnsiConsole.Progress().AutoClear(true).Start(ctx =>
                {
                    var task = ctx.AddTask("Baking files", maxValue: entries.Count);
                    foreach (DataManifest.Entry e in entries)
                    {
                        rows.Add(ScoreFile(e, every, inbetweeners));
                        task.Increment(1);
                    }
                });
                Print(rows, names, every);
                if (jsonFull != null)
                {
                    string json = Json(rows, names, models, every);
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

        private static Row ScoreFile(DataManifest.Entry e, int every, List<Inbetweener> models)
        {
            BvhAnimation animation = BakeInput.WithFrameRate(BvhReader.Read(e.FilePath), e.Fps);
            var row = new Row { File = e.Name, Group = e.Group, Position = new double[models.Count + 1], L2Q = new double[models.Count + 1] };
            for (int i = 0; i < models.Count; i++)
            {
                JointMap? map = BakeInput.LoadMap(e.Map, animation, models[i].Contract);
                int[] keys = BakeInput.Every(every, animation.Motion, e.FromFrame, models[i].Contract, e.FilePath);
                BakeOutcome outcome = BakeVerb.BakeBoth(animation, e.FilePath, keys, models[i], null, true, e.ReferenceFrame, map, quiet: true);
                BakeAccuracy model = BakeAccuracy.Measure(animation.Motion, outcome.ModelOut, keys);
                row.Leg = BakeInput.LegLength(outcome.Seam, models[i].Contract, animation);
                row.Frames = model.Frames;
                row.Position[i] = model.MeanPositionError / row.Leg;
                row.L2Q[i] = model.L2Q;
                if (i == 0)
                {
                    BakeAccuracy slerp = BakeAccuracy.Measure(animation.Motion, outcome.SlerpOut, keys);
                    row.Position[models.Count] = slerp.MeanPositionError / row.Leg;
                    row.L2Q[models.Count] = slerp.L2Q;
                }
            }

            for (int i = 0; i < row.Position.Length; i++)
            {
                if (!double.IsFinite(row.Position[i]) || !double.IsFinite(row.L2Q[i]))
                {
                    throw new CliErrors.UsageException($"{e.FilePath}: non-finite errors; expected finite motion values");
                }
            }

            return row;
        }

        private static (double[] Position, double[] L2Q, int Frames) Total(IEnumerable<Row> rows, int methods)
        {
            var p = new double[methods];
            var q = new double[methods];
            int frames = 0;
            foreach (Row r in rows)
            {
                frames += r.Frames;
                for (int i = 0; i < methods; i++)
                {
                    p[i] += r.Position[i] * r.Frames;
                    q[i] += r.L2Q[i] * r.Frames;
                }
            }

            for (int i = 0; i < methods; i++)
            {
                p[i] /= Math.Max(1, frames);
                q[i] /= Math.Max(1, frames);
            }

            return (p, q, frames);
        }

        private static void Print(List<Row> rows, List<string> names, int every)
        {
            int methods = names.Count;
            var table = new Table().Border(TableBorder.Rounded)
                .Title($"[bold]Keys every {every} input frames[/]: mean joint position error ÷ leg length, and L2Q, over non-key frames (× SLERP in brackets; lower is better)");
            table.AddColumn("File");
            table.AddColumn(new TableColumn("Frames").RightAligned());
            foreach (string n in names) table.AddColumn(new TableColumn(Markup.Escape(n) + " pos / L2Q").RightAligned());
            void AddRow(string label, double[] p, double[] q, int frames, bool bold)
            {
                var cells = new List<string> { bold ? $"[bold]{Markup.Escape(label)}[/]" : Markup.Escape(label), frames.ToString("N0", CultureInfo.InvariantCulture) };
                for (int i = 0; i < methods; i++)
                {
                    string cell = string.Format(CultureInfo.InvariantCulture, "{0:0.0000} / {1:0.000}", p[i], q[i]);
                    if (i < methods - 1) cell += string.Format(CultureInfo.InvariantCulture, " ({0:0.00} / {1:0.00})", p[i] / p[methods - 1], q[i] / q[methods - 1]);
                    cells.Add(cell);
                }

                table.AddRow(cells.ToArray());
            }

            foreach (Row r in rows) AddRow(r.File, r.Position, r.L2Q, r.Frames, false);
            var groups = new SortedDictionary<string, List<Row>>(StringComparer.Ordinal);
            foreach (Row r in rows)
            {
                if (r.Group.Length == 0) continue;
                if (!groups.TryGetValue(r.Group, out List<Row>? list)) groups[r.Group] = list = new List<Row>();
                list.Add(r);
            }

            if (groups.Count > 1)
            {
                foreach (var g in groups)
                {
                    var t = Total(g.Value, methods);
                    AddRow("subject " + g.Key, t.Position, t.L2Q, t.Frames, true);
                }
            }

            var all = Total(rows, methods);
            AddRow($"all {rows.Count} files", all.Position, all.L2Q, all.Frames, true);
            AnsiConsole.Write(table);
        }

        private static string Json(List<Row> rows, List<string> names, List<string> paths, int every)
        {
            int methods = names.Count;
            using var buffer = new MemoryStream();
            using (var w = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
            {
                void Methods(string key, double[] p, double[] q)
                {
                    w.WriteStartObject(key);
                    for (int i = 0; i < methods; i++)
                    {
                        w.WriteStartObject(i < methods - 1 ? names[i] : "slerp");
                        w.WriteNumber("position_per_leg", p[i]);
                        w.WriteNumber("l2q", q[i]);
                        w.WriteNumber("position_vs_slerp", p[i] / p[methods - 1]);
                        w.WriteNumber("l2q_vs_slerp", q[i] / q[methods - 1]);
                        w.WriteEndObject();
                    }

                    w.WriteEndObject();
                }

                w.WriteStartObject();
                w.WriteNumber("every", every);
                w.WriteStartArray("models");
                foreach (string p in paths) w.WriteStringValue(p);
                w.WriteEndArray();
                w.WriteStartArray("files");
                foreach (Row r in rows)
                {
                    w.WriteStartObject();
                    w.WriteString("file", r.File);
                    w.WriteString("group", r.Group);
                    w.WriteNumber("non_key_frames", r.Frames);
                    w.WriteNumber("leg_length", r.Leg);
                    Methods("methods", r.Position, r.L2Q);
                    w.WriteEndObject();
                }

                w.WriteEndArray();
                var groups = new SortedDictionary<string, List<Row>>(StringComparer.Ordinal);
                foreach (Row r in rows)
                {
                    if (!groups.TryGetValue(r.Group, out List<Row>? list)) groups[r.Group] = list = new List<Row>();
                    list.Add(r);
                }

                w.WriteStartObject("groups");
                foreach (var g in groups)
                {
                    var t = Total(g.Value, methods);
                    w.WriteStartObject(g.Key.Length == 0 ? "-" : g.Key);
                    w.WriteNumber("non_key_frames", t.Frames);
                    Methods("methods", t.Position, t.L2Q);
                    w.WriteEndObject();
                }

                w.WriteEndObject();
                var all = Total(rows, methods);
                w.WriteStartObject("total");
                w.WriteNumber("files", rows.Count);
                w.WriteNumber("non_key_frames", all.Frames);
                Methods("methods", all.Position, all.L2Q);
                w.WriteEndObject();
                w.WriteEndObject();
            }

            return Encoding.UTF8.GetString(buffer.ToArray()) + "\n";
        }
    }
}
