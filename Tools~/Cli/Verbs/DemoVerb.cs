using System;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Preview;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween demo</c>: the whole pipeline on the bundled CMU clip with no argument: retarget onto the
    /// model's skeleton, keep a key every half second, bake with SLERP and the shipped model, map back onto
    /// the CMU skeleton, write the BVH files and a preview into a new folder, and print both methods' error.
    /// </summary>
    public sealed class DemoVerb : ICliVerb
    {
        /// <summary>The demo clip, relative to the repository (package) root.</summary>
        internal const string Sample = "Samples~/Demo/cmu_09_12_walk_navigate.bvh";

        /// <summary>The sample's frame 0 is the T-pose B. Hahne's conversion adds: its reference pose, never a key.</summary>
        private const int ReferenceFrame = 0;

        private const string ShippedModel = ShippedModels.Default;

        /// <summary>
        /// Keys every 15 model frames (0.5 s at 30 fps, 60 frames of the 120 fps clip): gaps of 14 frames, inside
        /// the gap lengths the shipped models were trained on, and the spacing of the held-out scores in the model
        /// card ("keys every 15 model frames"), so the demo shows on one clip what the card reports over many.
        /// The clip is from a subject no shipped model was trained on or chosen by (CMU subject 9).
        /// </summary>
        private const int ModelFramesBetweenKeys = 15;

        private readonly Option<string?> _out = new Option<string?>("--out")
        {
            Description = "The folder to write into (created; refused when it exists and is not empty, unless --force). Default: a new out/demo-YYYYMMDD-HHMMSS under the current folder.",
            HelpName = "DIR",
        };

        private readonly Option<string?> _model = new Option<string?>("--model")
        {
            Description = "Exported model (NAME.onnx). Default: the shipped " + ShippedModel + ".",
            HelpName = "FILE.onnx",
        };

        private readonly OutputOptions _output = new OutputOptions();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "demo",
                "The whole pipeline on the bundled clip " + Sample + " (CMU, 120 fps, 31 joints), no data needed:\n" +
                "retarget it onto the model's skeleton at its rate, keep a key every " + ModelFramesBetweenKeys + " model frames (0.5 s), fill the gaps with\n" +
                "SLERP and with the model, map the model's result back onto the CMU skeleton, and write into a new folder:\n" +
                "ground-truth.bvh, slerp.bvh, model.bvh (model skeleton, 30 fps), model-on-source.bvh (CMU skeleton, 120 fps),\n" +
                "preview.html (player: ground truth, SLERP, model) and preview.png (contact sheet; an SVG without Chromium).\n" +
                "Prints each method's error against the clip's own frames between the keys.\n" +
                "Examples:\n" +
                "  inbetween demo\n" +
                "  inbetween demo --out out/demo --force");
            command.Options.Add(_out);
            command.Options.Add(_model);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            var total = Stopwatch.StartNew();
            bool force = parse.GetValue(_output.Force);
            string? root = FindRoot();
            if (root == null)
            {
                throw new CliErrors.UsageException($"{Sample}: not found above the current folder ({Directory.GetCurrentDirectory()}) nor above the tool ({AppContext.BaseDirectory}); expected to run inside the package checkout, which ships the demo clip");
            }

            string sample = Path.Combine(root, Sample);
            string modelPath = parse.GetValue(_model) ?? ShippedModels.Find(Path.Combine(root, ShippedModel));
            if (!File.Exists(modelPath)) throw new CliErrors.UsageException($"{modelPath}: no such file; expected an exported model (NAME.onnx), e.g. {ShippedModel}");
            string folder = parse.GetValue(_out) ?? Path.Combine("out", "demo-" + DateTime.Now.ToString("yyyyMMdd-HHmmss", CultureInfo.InvariantCulture));

            // Before any work: a new or empty folder (or --force), and every file in it writable.
            if (File.Exists(folder)) throw new CliErrors.UsageException($"{folder}: is a file; expected a folder for the demo's files");
            if (Directory.Exists(folder) && Directory.EnumerateFileSystemEntries(folder).Any() && !force)
            {
                throw new CliErrors.UsageException($"{folder}: folder exists and is not empty; expected a new or empty folder, or --force to write the demo's files into it");
            }

            string truthPath = Path.Combine(folder, "ground-truth.bvh");
            string slerpPath = Path.Combine(folder, "slerp.bvh");
            string modelBvh = Path.Combine(folder, "model.bvh");
            string onSourcePath = Path.Combine(folder, "model-on-source.bvh");
            string htmlPath = Path.Combine(folder, "preview.html");
            string pngPath = Path.Combine(folder, "preview.png");
            foreach (string path in new[] { truthPath, slerpPath, modelBvh, onSourcePath })
            {
                OutputFile.Check(path, force, sample, modelPath);
            }

            BakeVerb.CheckPreviewOutputs(htmlPath, pngPath, new[] { truthPath, slerpPath, modelBvh, onSourcePath }, force, sample, modelPath);

            BvhAnimation animation = BvhReader.Read(sample);
            using var model = new Inbetweener(OnnxRuntimeBackend.Load(modelPath, new OnnxRuntimeOptions { IntraOpThreads = 1 }));
            int[] keys = DemoKeys(animation.Motion, model.Contract);
            BakeOutcome outcome = BakeVerb.BakeBoth(animation, sample, keys, model, null, true, ReferenceFrame);

            Directory.CreateDirectory(folder);
            WriteBvh(RetargetVerb.ModelAnimation(BakeVerb.Excerpt(outcome.GroundTruthOnModel, 0, outcome.ModelOnModel.FrameCount), truthPath), truthPath);
            WriteBvh(RetargetVerb.ModelAnimation(outcome.SlerpOnModel, slerpPath), slerpPath);
            WriteBvh(RetargetVerb.ModelAnimation(outcome.ModelOnModel, modelBvh), modelBvh);
            WriteBvh(new BvhAnimation(outcome.ModelOut, animation.JointChannels, animation.EndSites, onSourcePath), onSourcePath);

            BakeAccuracy modelScore = BakeAccuracy.Measure(animation.Motion, outcome.ModelOut, keys);
            BakeAccuracy slerpScore = BakeAccuracy.Measure(animation.Motion, outcome.SlerpOut, keys);
            BakeAccuracy modelOnModel = BakeAccuracy.Measure(outcome.GroundTruthOnModel, outcome.ModelOnModel, outcome.ModelKeys);
            BakeAccuracy slerpOnModel = BakeAccuracy.Measure(outcome.GroundTruthOnModel, outcome.SlerpOnModel, outcome.ModelKeys);

            var table = new Table().Border(TableBorder.Rounded)
                .Title(Markup.Escape($"{Path.GetFileName(sample)}: error on the {modelScore.Frames:N0} non-key frames of the clip (lower is better)"));
            table.AddColumn("Method");
            table.AddColumn(new TableColumn("Joint pos. error (file units)").RightAligned());
            table.AddColumn(new TableColumn("L2Q").RightAligned());
            table.AddColumn(new TableColumn("On model skeleton (its units)").RightAligned());
            table.AddColumn(new TableColumn("Bake (s)").RightAligned());
            AddRow(table, "SLERP", slerpScore, slerpOnModel, outcome.SlerpSeconds);
            AddRow(table, "Model", modelScore, modelOnModel, outcome.ModelSeconds);
            AnsiConsole.Write(table);
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "{0} frames at {1:0.##} fps, {2} keys every {3} frames ({4} model frames, {5:0.##} s); {6}",
                animation.Motion.FrameCount, 1 / animation.Motion.FrameTime, keys.Length, keys[1] - keys[0], ModelFramesBetweenKeys,
                ModelFramesBetweenKeys / model.Contract.FramesPerSecond, outcome.Seam.Description)));
            AnsiConsole.MarkupLine(Markup.Escape($"Model: {modelPath}; errors between the keys against the original CMU frames (model results mapped back) and against the retargeted clip on the model's skeleton"));
            if (outcome.Seam is SkeletonRetargeting retargeted) AnsiConsole.MarkupLine(Markup.Escape(BakeVerb.KeyLine(retargeted)));
            foreach (string warning in outcome.ModelPlan.Warnings) AnsiConsole.MarkupLine("[yellow]warning:[/] " + Markup.Escape(warning));

            BakeVerb.WritePreview(animation, keys, outcome, htmlPath, pngPath, force);
            AnsiConsole.MarkupLine(Markup.Escape($"wrote into {Path.GetFullPath(folder)}:"));
            foreach (string path in Directory.EnumerateFiles(folder).OrderBy(p => p, StringComparer.Ordinal))
            {
                AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture, "  {0,-22} {1,8:0} KB", Path.GetFileName(path), new FileInfo(path).Length / 1024.0)));
            }

            string sheet = File.Exists(pngPath) ? pngPath : ContactSheet.OutputPathFor(pngPath);
            AnsiConsole.MarkupLine(Markup.Escape($"open {Path.GetFullPath(htmlPath)} in a browser (plays ground truth, SLERP and model side by side; keys marked), and {Path.GetFullPath(sheet)} for the contact sheet; the BVH files open in Blender or any BVH viewer"));
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture, "total {0:0.0} s", total.Elapsed.TotalSeconds)));
            return 0;
        }

        /// <summary>A key every <see cref="ModelFramesBetweenKeys"/> model frames in the clip's own frames, from the frame after the reference T-pose to the last whole interval.</summary>
        private static int[] DemoKeys(MotionClip clip, ModelContract contract)
        {
            int every = (int)Math.Round(ModelFramesBetweenKeys / contract.FramesPerSecond / clip.FrameTime);
            int first = ReferenceFrame + 1;
            int last = first + (clip.FrameCount - 1 - first) / every * every;
            return KeyFrames.Every(every, last + 1, first, 1);
        }

        private static void AddRow(Table table, string name, BakeAccuracy onSource, BakeAccuracy onModel, double seconds)
        {
            table.AddRow(
                Markup.Escape(name),
                onSource.MeanPositionError.ToString("0.000", CultureInfo.InvariantCulture),
                onSource.L2Q.ToString("0.0000", CultureInfo.InvariantCulture),
                onModel.MeanPositionError.ToString("0.00", CultureInfo.InvariantCulture),
                seconds.ToString("0.000", CultureInfo.InvariantCulture));
        }

        private static void WriteBvh(BvhAnimation animation, string path)
        {
            OutputFile.Write(path, stream =>
            {
                using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
                BvhWriter.Write(animation, writer);
            });
        }

        /// <summary>The package root holding the demo clip: above the current folder, else above the tool's own files.</summary>
        internal static string? FindRoot()
        {
            foreach (string start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
            {
                string? dir = start;
                while (!string.IsNullOrEmpty(dir))
                {
                    if (File.Exists(Path.Combine(dir, Sample))) return dir;
                    dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
                }
            }

            return null;
        }
    }
}
