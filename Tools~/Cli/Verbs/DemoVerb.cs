using System;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using DeltaInterpolator.Cli.Baking;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
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
            string sample = ShippedModels.Find(Sample);
            if (!File.Exists(sample))
            {
                throw new CliErrors.UsageException($"{Sample}: not found above the current folder ({Directory.GetCurrentDirectory()}) nor above the tool ({AppContext.BaseDirectory}); expected to run inside the package checkout, which ships the demo clip");
            }

            string modelPath = parse.GetValue(_model) ?? ShippedModels.Find(ShippedModel);
            if (!File.Exists(modelPath)) throw new CliErrors.UsageException($"{modelPath}: no such file; expected an exported model (NAME.onnx), e.g. {ShippedModel}");
            string folder = parse.GetValue(_out) ?? Path.Combine("out", "demo-" + DateTime.Now.ToString("yyyyMMdd-HHmmss", CultureInfo.InvariantCulture));

            // Before any work: a new or empty folder (or --force), and every file in it writable.
            if (File.Exists(folder)) throw new CliErrors.UsageException($"{folder}: is a file; expected a folder for the demo's files");
            if (Directory.Exists(folder) && Directory.EnumerateFileSystemEntries(folder).Any() && !force)
            {
                throw new CliErrors.UsageException($"{folder}: folder exists and is not empty; expected a new or empty folder, or --force to write the demo's files into it");
            }

            string[] bvhs = { "ground-truth.bvh", "slerp.bvh", "model.bvh", "model-on-source.bvh" };
            for (int i = 0; i < bvhs.Length; i++) bvhs[i] = OutputFile.Check(Path.Combine(folder, bvhs[i]), force, sample, modelPath);
            string htmlPath = Path.Combine(folder, "preview.html");
            string pngPath = Path.Combine(folder, "preview.png");
            BakePreview.CheckOutputs(htmlPath, pngPath, bvhs, force, sample, modelPath);

            BvhAnimation animation = BvhReader.Read(sample);
            using Inbetweener model = InbetweenerLoader.Load(new OnnxModelFiles(modelPath, new OnnxRuntimeOptions { IntraOpThreads = 1 }), LazyGraphs.None);
            int[] keys = DemoKeys(animation.Motion, model.Contract);
            BakeRun run = BakeInput.Bake(animation, sample, keys, model.Contract, BakeInput.ModelAndSlerp(model, null, true, null), ReferenceFrame, null);
            MethodBake modelBake = run["Model"], slerpBake = run["SLERP"];

            Directory.CreateDirectory(folder);
            WriteBvh(BvhAnimation.ForSkeleton(run.GroundTruthOnModel.Excerpt(0, modelBake.OnModel.FrameCount), bvhs[0]), bvhs[0]);
            WriteBvh(BvhAnimation.ForSkeleton(slerpBake.OnModel, bvhs[1]), bvhs[1]);
            WriteBvh(BvhAnimation.ForSkeleton(modelBake.OnModel, bvhs[2]), bvhs[2]);
            WriteBvh(new BvhAnimation(modelBake.OnRig, animation.JointChannels, animation.EndSites, bvhs[3]), bvhs[3]);

            BakeScores scores = BakeScores.Measure(animation.Motion, run);
            BakeAccuracy modelOnModel = BakeAccuracy.Measure(run.GroundTruthOnModel, modelBake.OnModel, run.ModelKeys);
            BakeAccuracy slerpOnModel = BakeAccuracy.Measure(run.GroundTruthOnModel, slerpBake.OnModel, run.ModelKeys);

            var table = new Table().Border(TableBorder.Rounded)
                .Title(Markup.Escape($"{Path.GetFileName(sample)}: error on the {scores["Model"].Accuracy.Frames:N0} non-key frames of the clip (lower is better)"));
            table.AddColumn("Method");
            table.AddColumn(new TableColumn("Joint pos. error (file units)").RightAligned());
            table.AddColumn(new TableColumn("L2Q").RightAligned());
            table.AddColumn(new TableColumn("On model skeleton (its units)").RightAligned());
            table.AddColumn(new TableColumn("Bake (s)").RightAligned());
            AddRow(table, "SLERP", scores["SLERP"].Accuracy, slerpOnModel, slerpBake.Seconds);
            AddRow(table, "Model", scores["Model"].Accuracy, modelOnModel, modelBake.Seconds);
            AnsiConsole.Write(table);
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "{0} frames at {1:0.##} fps, {2} keys every {3} frames ({4} model frames, {5:0.##} s); {6}",
                animation.Motion.FrameCount, 1 / animation.Motion.FrameTime, keys.Length, keys[1] - keys[0], ModelFramesBetweenKeys,
                ModelFramesBetweenKeys / model.Contract.FramesPerSecond, run.Rig.Description)));
            AnsiConsole.MarkupLine(Markup.Escape($"Model: {modelPath}; errors between the keys against the original CMU frames (model results mapped back) and against the retargeted clip on the model's skeleton"));
            string? keyLine = BakeInput.KeyLine(run.Rig);
            if (keyLine != null) AnsiConsole.MarkupLine(Markup.Escape(keyLine));
            foreach (string warning in modelBake.Plan.Warnings) AnsiConsole.MarkupLine("[yellow]warning:[/] " + Markup.Escape(warning));

            BakePreview.Write(animation, run, htmlPath, pngPath, force);
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
    }
}
