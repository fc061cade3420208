using System.CommandLine;
using System.Diagnostics;
using System.IO;
using System.Text;
using DeltaInterpolator.Cli.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.OnnxRuntime;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween bake IN.bvh --keys …|--every K --out OUT.bvh</c>: keeps the key frames of a BVH file,
    /// fills every gap between them with the model and SLERP (Core's <see cref="InbetweenBake"/>), writes the
    /// chosen method's BVH and prints both methods' scores against the file's own frames
    /// (<see cref="BakeScores"/>). Parses (<see cref="BakeOptions"/>), calls, prints (<see cref="BakeSummary"/>).
    /// </summary>
    public sealed class BakeVerb : ICliVerb
    {
        private readonly BakeOptions _options = new BakeOptions();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "bake",
                "Keep a BVH file's key frames and fill every gap between them, in order, with the neural model (past context: up to\n" +
                "the model's past frames before the gap, keys and frames already filled; future: the next key) or with SLERP.\n" +
                "Writes the chosen method's BVH and prints, for both methods, the error against the file's own frames on the\n" +
                "non-key frames: mean global joint position error (file units), L2Q, and L2P with the official statistics for\n" +
                "LaFAN1-skeleton files. Gaps outside the model's trained lengths are baked with a warning; a gap its graph cannot\n" +
                "take is refused.\n" +
                "Any humanoid BVH: one on the model's skeleton at its rate is baked as is; any other (e.g. CMU at 120 fps) is\n" +
                "retargeted onto the model's skeleton and rate (as 'retarget' does), baked there, and mapped back onto its own\n" +
                "skeleton and rate, its key frames kept exactly. --preview writes an HTML player of ground truth, SLERP and model.\n" +
                "Examples:\n" +
                "  inbetween bake ../shared/data/lafan1/obstacles1_subject5.bvh --every 15 --out out/obstacles1-every15.bvh --force\n" +
                "  inbetween bake Samples~/Demo/cmu_09_12_walk_navigate.bvh --every 60 --reference-frame 0 --from-frame 1 --out out/walk-every60.bvh --json out/walk-every60.json --preview out/walk.html --png out/walk.png --force\n" +
                "  inbetween bake ../shared/data/cmu-more/60_01.bvh --input-fps 60 --from-frame 10 --every 30 --out out/salsa.bvh --force");
            _options.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            var total = Stopwatch.StartNew();
            BakeRequest r = _options.Parse(parse);
            var read = Stopwatch.StartNew();
            BvhAnimation animation = BakeInput.WithFrameRate(BvhReader.Read(r.Input), r.InputFps);
            MotionChecks.RequireFinitePositions(animation.Motion, r.Input, "the input");
            MotionChecks.RequireFrame(animation.Motion, r.ReferenceFrame, "--reference-frame", r.Input);
            double readSeconds = read.Elapsed.TotalSeconds;

            var load = Stopwatch.StartNew();
            // The whole graph only: baking runs whole transitions, so the lazy graphs would only cost load time.
            using Inbetweener model = InbetweenerLoader.Load(new OnnxModelFiles(r.ModelPath, new OnnxRuntimeOptions { IntraOpThreads = r.Threads }), LazyGraphs.None);
            double loadSeconds = load.Elapsed.TotalSeconds;
            JointMap? jointMap = BakeInput.LoadMap(r.MapPath, animation, model.Contract);
            int[] keys = r.Keys != null
                ? BakeInput.CheckFrom(r.Keys, r.FromFrame, r.Input)
                : BakeInput.Every(r.Every!.Value, animation.Motion, r.FromFrame, model.Contract, r.Input);
            if (r.Every.HasValue)
            {
                // The spacing in all three units: a bare number is input frames, which mean different times at 30, 60 and 120 fps.
                AnsiConsole.MarkupLine(Markup.Escape($"keys {r.Every.Value.Describe(animation.Motion.FrameTime, model.Contract.FramesPerSecond)} from frame {r.FromFrame}: {keys.Length} keys"));
            }

            BakeRun run = BakeInput.Bake(animation, r.Input, keys, model.Contract, BakeInput.ModelAndSlerp(model, r.Policy, r.FilledContext, r.Feet), r.ReferenceFrame, jointMap, up: r.Up, acceptReferencePose: r.AcceptReferencePose);
            // Before OUT.bvh, the scores or the preview: a NaN or overflow is refused, never written or drawn.
            MotionChecks.RequireFinitePositions(run["Model"].OnRig, r.Input, "the model's result");
            MotionChecks.RequireFinitePositions(run["SLERP"].OnRig, r.Input, "the SLERP result");
            BenchmarkStatistics? statistics = LoadStatistics(r.StatsPath, r.StatsGiven, animation.Skeleton, r.Input);

            MotionClip chosen = run[r.Method == "model" ? "Model" : "SLERP"].OnRig;
            var written = new BvhAnimation(chosen, animation.JointChannels, animation.EndSites, r.OutPath);
            Write(r.OutFull, w => BvhWriter.Write(written, w));

            BakeScores scores = BakeScores.Measure(animation.Motion, run, statistics?.StandardDeviation);
            BakeSummary.Print(r, animation, run, scores, model.Contract, statistics, readSeconds, loadSeconds, total.Elapsed.TotalSeconds);
            if (r.JsonFull != null)
            {
                string json = BakeReport.Json(r.Input, animation, run, scores, model.Contract, r.ModelPath, r.Feet != null);
                Write(r.JsonFull, w => w.Write(json));
                AnsiConsole.MarkupLine(Markup.Escape("wrote " + r.JsonPath));
            }

            if (r.PreviewPath != null) BakePreview.Write(animation, run, r.PreviewPath, r.PngPath, r.Force);
            return 0;
        }

        private static void Write(string path, System.Action<StreamWriter> write) => OutputFile.Write(path, stream =>
        {
            using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
            write(writer);
        });

        private static BenchmarkStatistics? LoadStatistics(string? path, bool given, Skeleton skeleton, string input)
        {
            if (path == null) return null;
            BenchmarkStatistics statistics = BenchmarkStatistics.Load(path);
            try
            {
                statistics.SkeletonFor(skeleton, input);
                return statistics;
            }
            catch (Core.DataFormatException) when (!given)
            {
                // The default statistics are LaFAN1's: another skeleton simply gets no L2P.
                return null;
            }
        }
    }
}
