using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Preview;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween bake IN.bvh --keys …|--every K --out OUT.bvh</c>: keeps the key frames of a BVH file,
    /// fills every gap between them with the model or SLERP (Core's <see cref="ClipBaker"/>), writes the
    /// chosen method's BVH and prints both methods' error against the file's own frames.
    /// </summary>
    public sealed class BakeVerb : ICliVerb
    {
        private const string ShippedModel = ShippedModels.Default;
        private const string DefaultStats = "../shared/data/lafan1/train_stats_official.json";

        private readonly Argument<string> _input = new Argument<string>("IN.bvh")
        {
            Description = "BVH file of a humanoid: on the model's skeleton at its rate (LaFAN1, 30 fps) it is baked as is, any other (e.g. CMU at 120 fps) is retargeted onto the model's skeleton and rate and the results mapped back; its frames are the keys' source and the ground truth.",
        };

        private readonly Option<string?> _keys = new Option<string?>("--keys")
        {
            Description = "Key frame indices of IN.bvh, increasing, comma-separated (at least two), or @FILE for a file of them (commas, spaces or lines). The output spans the first to the last key.",
            HelpName = "F,F,...",
        };

        private readonly Option<int?> _every = new Option<int?>("--every")
        {
            Description = "A key every K frames: 0, K, 2K, … and the file's last frame.",
            HelpName = "K",
        };

        private readonly Option<string> _method = new Option<string>("--method")
        {
            Description = "Which method's result OUT.bvh holds: the neural model or SLERP (both are always scored).",
            HelpName = "model|slerp",
            DefaultValueFactory = _ => "model",
        };

        private readonly Option<string?> _model = new Option<string?>("--model")
        {
            Description = "Exported model (NAME.onnx). Default: the shipped " + ShippedModel + ".",
            HelpName = "FILE.onnx",
        };

        private readonly Option<string> _pastPolicy = new Option<string>("--past-policy")
        {
            Description = "What the model gets where fewer past frames exist than it wants (a clip's first gaps): 'auto' from the model's trained past range (fixed 10 → repeat, from 1 → feed), 'feed' the frames that exist, 'repeat' the earliest repeated.",
            HelpName = "auto|feed|repeat",
            DefaultValueFactory = _ => "auto",
        };

        private readonly Option<string> _context = new Option<string>("--context")
        {
            Description = "Past context of a gap: 'filled' = key frames and frames already filled (default), 'keys' = key frames only (the key before the gap, laid out by --past-policy).",
            HelpName = "filled|keys",
            DefaultValueFactory = _ => "filled",
        };

        private readonly Option<string> _out = new Option<string>("--out")
        {
            Description = "Output BVH file (same joints and channels as IN.bvh).",
            HelpName = "OUT.bvh",
            Required = true,
        };

        private readonly OutputOptions _output = new OutputOptions();

        private readonly Option<int?> _referenceFrame = new Option<int?>("--reference-frame")
        {
            Description = "For input on another skeleton (retargeted): the input frame that is its reference pose (e.g. 0 for a CMU file's T-pose); default: its default pose (see 'retarget --help').",
            HelpName = "K",
        };

        private readonly Option<string?> _map = new Option<string?>("--map")
        {
            Description = "A JSON joint map {\"ModelJoint\": \"sourceJoint\" or [\"chain\"] or null, …} for names the built-in maps miss (the format 'retarget --map' reads; null or omitted: a joint the rig lacks, synthesized).",
            HelpName = "MAP.json",
        };

        private readonly Option<double?> _inputFps = new Option<double?>("--input-fps")
        {
            Description = "The input's true frame rate when its header is wrong (CMU subjects 60 and 61: 60 fps, the header says 120); the output says it too.",
            HelpName = "F",
        };

        private readonly Option<int?> _fromFrame = new Option<int?>("--from-frame")
        {
            Description = "The first frame that may be a key (frames before it — a T-pose, conversion artefacts — are never keys and never scored); --every counts from it.",
            HelpName = "K",
        };

        private readonly Option<string> _feet = new Option<string>("--feet")
        {
            Description = "Foot locking of both methods' filled frames before they are mapped back: 'lock' holds planted feet still (two-bone IK, key frames untouched), 'off' leaves them as filled (default: lock). Foot skating is reported either way.",
            HelpName = "lock|off",
            // On by default: with the default (CMU) model locking keeps the position error within 2 % of 'off' on every
            // measured bake (demo clip −0.4 %, worst +1.1 %) and cuts the demo clip's foot skating 0.265 → 0.148 leg/s.
            DefaultValueFactory = _ => "lock",
        };

        private readonly Option<string?> _json = new Option<string?>("--json")
        {
            Description = "Also write each method's scores as JSON: mean joint position error (file units and ÷ leg length), L2Q, L2P, non-key frames (what 'score' adds up over folders).",
            HelpName = "OUT.json",
        };

        private readonly Option<string?> _preview = new Option<string?>("--preview")
        {
            Description = "Also write a self-contained HTML player of ground truth, SLERP and model over the baked frames (input's skeleton).",
            HelpName = "OUT.html",
        };

        private readonly Option<string?> _png = new Option<string?>("--png")
        {
            Description = "With --preview: also a PNG contact sheet (headless Chromium; without it, an SVG beside it instead).",
            HelpName = "OUT.png",
        };

        private readonly Option<string?> _stats = new Option<string?>("--stats")
        {
            Description = "Statistics JSON for L2P on LaFAN1-skeleton files. Default: " + DefaultStats + " when present.",
            HelpName = "FILE",
        };

        private readonly Option<int> _threads = new Option<int>("--threads")
        {
            Description = "ONNX Runtime intra-op threads.",
            HelpName = "N",
            DefaultValueFactory = _ => 1,
        };

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
            command.Arguments.Add(_input);
            command.Options.Add(_keys);
            command.Options.Add(_every);
            command.Options.Add(_method);
            command.Options.Add(_model);
            command.Options.Add(_pastPolicy);
            command.Options.Add(_context);
            command.Options.Add(_out);
            _output.AddTo(command);
            command.Options.Add(_referenceFrame);
            command.Options.Add(_map);
            command.Options.Add(_inputFps);
            command.Options.Add(_fromFrame);
            command.Options.Add(_feet);
            command.Options.Add(_json);
            command.Options.Add(_preview);
            command.Options.Add(_png);
            command.Options.Add(_stats);
            command.Options.Add(_threads);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            var total = Stopwatch.StartNew();
            string input = parse.GetValue(_input)!;
            string? keysText = parse.GetValue(_keys);
            int? every = parse.GetValue(_every);
            string method = parse.GetValue(_method)!;
            string outPath = parse.GetValue(_out)!;
            bool force = parse.GetValue(_output.Force);
            int threads = parse.GetValue(_threads);
            ShortContextPolicy? policy = ParsePolicy(parse.GetValue(_pastPolicy)!);
            FootLockSettings? feet = BakeFeet.Parse(parse.GetValue(_feet)!);

            if ((keysText == null) == (every == null))
            {
                throw new CliErrors.UsageException("inbetween bake: " + (keysText == null ? "neither --keys nor --every given" : "both --keys and --every given") + "; expected exactly one of them");
            }

            if (method != "model" && method != "slerp")
            {
                throw new CliErrors.UsageException($"inbetween bake: --method '{method}'; expected model or slerp");
            }

            string context = parse.GetValue(_context)!;
            if (context != "filled" && context != "keys")
            {
                throw new CliErrors.UsageException($"inbetween bake: --context '{context}'; expected filled or keys");
            }

            if (threads < 1) throw new CliErrors.UsageException($"inbetween bake: --threads {threads}; expected 1 or more");
            InputFile.Check(input, "a .bvh file");
            string modelPath = parse.GetValue(_model) ?? ShippedModels.Find(ShippedModel);
            InputFile.Check(modelPath, $"an exported model (NAME.onnx), e.g. {ShippedModel}");
            string? statsGiven = parse.GetValue(_stats);
            if (statsGiven != null) InputFile.Check(statsGiven, $"a statistics JSON such as {DefaultStats}");
            string? statsPath = statsGiven ?? (File.Exists(DefaultStats) ? DefaultStats : null);

            string? mapPath = parse.GetValue(_map);
            if (mapPath != null) InputFile.Check(mapPath, "a JSON joint map"); // a folder, a named pipe or a device is refused as such
            double? inputFps = parse.GetValue(_inputFps);
            if (inputFps.HasValue && !(inputFps.Value >= 1 && inputFps.Value <= 1000))
            {
                throw new CliErrors.UsageException($"inbetween bake: --input-fps {inputFps.Value.ToString(CultureInfo.InvariantCulture)}; expected a frame rate from 1 to 1000");
            }

            int fromFrame = parse.GetValue(_fromFrame) ?? 0;
            if (fromFrame < 0) throw new CliErrors.UsageException($"inbetween bake: --from-frame {fromFrame}; expected a frame index from 0");

            // Before any work: the outputs must be writable and must not replace an input or each other.
            string outFull = OutputFile.Check(outPath, force, input, modelPath, statsPath, mapPath);
            string? jsonPath = parse.GetValue(_json);
            string? jsonFull = jsonPath == null ? null : OutputFile.Check(jsonPath, force, input, modelPath, statsPath, mapPath);
            if (jsonFull != null && string.Equals(jsonFull, outFull, StringComparison.Ordinal)) throw new CliErrors.UsageException($"{jsonPath}: the same file as --out; expected a different path for --json");
            string? previewPath = parse.GetValue(_preview);
            string? pngPath = parse.GetValue(_png);
            CheckPreviewOutputs(previewPath, pngPath, jsonFull == null ? new[] { outFull } : new[] { outFull, jsonFull }, force, input, modelPath, statsPath, mapPath);

            var read = Stopwatch.StartNew();
            BvhAnimation animation = BakeInput.WithFrameRate(BvhReader.Read(input), inputFps);
            MotionChecks.RequireFinitePositions(animation.Motion, input, "the input");
            double readSeconds = read.Elapsed.TotalSeconds;

            var load = Stopwatch.StartNew();
            // The whole graph only: baking runs whole transitions, so the lazy graphs would only cost load time.
            using var model = new Inbetweener(OnnxRuntimeBackend.Load(modelPath, new OnnxRuntimeOptions { IntraOpThreads = threads }));
            double loadSeconds = load.Elapsed.TotalSeconds;
            JointMap? jointMap = BakeInput.LoadMap(mapPath, animation, model.Contract);
            int[] inputKeys = keysText != null
                ? BakeInput.CheckFrom(ParseKeys(keysText, input), fromFrame, input)
                : BakeInput.Every(every!.Value, animation.Motion, fromFrame, model.Contract, input);

            BakeOutcome outcome = BakeBoth(animation, input, inputKeys, model, policy, context == "filled", parse.GetValue(_referenceFrame), jointMap, feet: feet);
            MotionClip modelOut = outcome.ModelOut, slerpOut = outcome.SlerpOut;
            // Before OUT.bvh, the scores or the preview: a NaN or overflow is refused, never written or drawn.
            MotionChecks.RequireFinitePositions(modelOut, input, "the model's result");
            MotionChecks.RequireFinitePositions(slerpOut, input, "the SLERP result");
            BakePlan modelPlan = outcome.ModelPlan;
            BenchmarkStatistics? statistics = LoadStatistics(statsPath, statsGiven != null, animation.Skeleton, input);

            MotionClip chosen = method == "model" ? modelOut : slerpOut;
            var written = new BvhAnimation(chosen, animation.JointChannels, animation.EndSites, outPath);
            OutputFile.Write(outFull, stream =>
            {
                using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
                BvhWriter.Write(written, writer);
            });

            double[]? std = statistics?.StandardDeviation;
            BakeAccuracy modelScore = BakeAccuracy.Measure(animation.Motion, modelOut, inputKeys, std);
            BakeAccuracy slerpScore = BakeAccuracy.Measure(animation.Motion, slerpOut, inputKeys, std);
            BakeFeet.Scores skating = BakeFeet.Measure(animation, inputKeys, outcome);
            PrintSummary(input, animation, inputKeys, modelPlan, outcome.ModelSettings, model.Contract, outcome.Seam, outPath, method,
                modelScore, slerpScore, statistics, outcome.ModelSeconds, outcome.SlerpSeconds, readSeconds, loadSeconds, total.Elapsed.TotalSeconds, skating, feet != null);
            if (jsonFull != null)
            {
                string json = BakeReport.Json(input, animation, inputKeys, outcome, model.Contract, modelPath, modelScore, slerpScore, skating, feet != null);
                OutputFile.Write(jsonFull, stream =>
                {
                    using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
                    writer.Write(json);
                });
                AnsiConsole.MarkupLine(Markup.Escape("wrote " + jsonPath));
            }
            if (previewPath != null)
            {
                WritePreview(animation, inputKeys, outcome, previewPath, pngPath, force);
            }

            return 0;
        }

        /// <summary>
        /// Both methods' bakes of <paramref name="animation"/>'s keys: on the model's skeleton and rate, and
        /// back on the input's. Same-skeleton inputs at the model's rate go straight in; any other humanoid
        /// is retargeted (<see cref="SkeletonRetargeting"/>). Progress of the model's gaps on stderr.
        /// </summary>
        internal static BakeOutcome BakeBoth(BvhAnimation animation, string input, int[] inputKeys, Inbetweener model, ShortContextPolicy? policy, bool filledContext, int? referenceFrame, JointMap? map = null, bool quiet = false, FootLockSettings? feet = null)
        {
            IBakeRetargeting seam = ChooseSeam(model.Contract, animation, input, referenceFrame, map);
            MotionClip source = seam.ToModel(animation, inputKeys);
            int[] modelKeys = seam.KeysToModel(inputKeys);

            BakeSettings modelSettings = BakeSettings.ForModel(model.Contract, policy);
            modelSettings.FilledFramesAsContext = filledContext;
            // Feet are locked on the model's skeleton, before the results are mapped back (both methods alike).
            modelSettings.FootLocking = feet;
            var modelBaker = new ClipBaker(model, modelSettings);
            // SLERP's feet slide steadily whatever the truth did: its timing says nothing about when a foot lifts.
            var slerpBaker = new ClipBaker(new SlerpBaseline(), new BakeSettings { Name = "SLERP", FootLocking = feet == null ? null : FootLockSettings.ForInterpolation() });
            BakePlan modelPlan = Plan(modelBaker, source.FrameCount, modelKeys, input);
            BakePlan slerpPlan = Plan(slerpBaker, source.FrameCount, modelKeys, input);

            MotionClip? modelClip = null, slerpClip = null;
            double modelSeconds = 0, slerpSeconds = 0;
            void Run(IProgress<int>? reporter)
            {
                var sw = Stopwatch.StartNew();
                modelClip = modelBaker.Bake(source, modelPlan, reporter);
                modelSeconds = sw.Elapsed.TotalSeconds;
                sw.Restart();
                slerpClip = slerpBaker.Bake(source, slerpPlan);
                slerpSeconds = sw.Elapsed.TotalSeconds;
            }

            if (quiet)
            {
                Run(null); // a caller with its own progress (score)
            }
            else
            {
                IAnsiConsole progressConsole = AnsiConsole.Create(new AnsiConsoleSettings
                {
                    Out = new AnsiConsoleOutput(Console.Error),
                    Interactive = Console.IsErrorRedirected ? InteractionSupport.No : InteractionSupport.Detect,
                });
                progressConsole.Progress()
                    .AutoClear(true)
                    .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn(), new RemainingTimeColumn())
                    .Start(ctx => Run(Console.IsErrorRedirected ? null : new GapProgress(new SpectreProgress(ctx), modelPlan.Gaps.Count)));
            }

            // Model skeleton and rate → input skeleton and rate.
            MotionClip modelOut = seam.FromModel(modelClip!, animation, inputKeys);
            MotionClip slerpOut = seam.FromModel(slerpClip!, animation, inputKeys);
            return new BakeOutcome(seam, source, modelKeys, modelPlan, modelSettings, modelClip!, slerpClip!, modelOut, slerpOut, modelSeconds, slerpSeconds);
        }

        /// <summary>The input as is when it is on the model's skeleton at its rate; otherwise retargeted.</summary>
        private static IBakeRetargeting ChooseSeam(ModelContract contract, BvhAnimation animation, string input, int? referenceFrame, JointMap? map)
        {
            bool sameSkeleton;
            try
            {
                contract.CheckSkeleton(animation.Skeleton, input);
                sameSkeleton = true;
            }
            catch (ModelContractException)
            {
                sameSkeleton = false;
            }

            double frameTime = 1.0 / contract.FramesPerSecond;
            // BVH files round their frame time (LaFAN1: 0.033333): within 0.01 % it is the model's rate.
            if (sameSkeleton && referenceFrame == null && map == null && Math.Abs(animation.Motion.FrameTime - frameTime) <= 1e-4 * frameTime)
            {
                return new SameSkeleton(contract, input);
            }

            return SkeletonRetargeting.Create(contract, animation, referenceFrame, input, map);
        }

        /// <summary>The HTML player (and contact sheet) of ground truth, SLERP and model over the baked frames, on the input's skeleton.</summary>
        internal static void WritePreview(BvhAnimation animation, int[] inputKeys, BakeOutcome outcome, string htmlPath, string? pngPath, bool force)
        {
            int first = inputKeys[0];
            MotionClip truth = Excerpt(animation.Motion, first, outcome.ModelOut.FrameCount);
            var keys = new int[inputKeys.Length];
            for (int i = 0; i < keys.Length; i++) keys[i] = inputKeys[i] - first;
            string title = Path.GetFileName(animation.SourceName) + $", frames {first}–{inputKeys[inputKeys.Length - 1]}";
            PreviewScene scene = PreviewScene.FromClips(title, new[] { ("Ground truth", truth), ("SLERP", outcome.SlerpOut), ("Model", outcome.ModelOut) }, keys, 0);
            PreviewWriter.WriteHtml(scene, htmlPath);
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB): ground truth, SLERP and model, {2} frames, {3} keys", htmlPath, new FileInfo(htmlPath).Length / 1024.0, scene.FrameCount, keys.Length)));
            if (pngPath == null) return;
            string? fallback = null;
            string written = pngPath;
            AnsiConsole.Status().Start("Rasterising the contact sheet with headless Chromium...", _ => written = ContactSheet.Write(scene, pngPath, force, out fallback));
            AnsiConsole.MarkupLine(Markup.Escape(fallback ?? string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB)", written, new FileInfo(written).Length / 1024.0)));
        }

        /// <summary>Frames start..start+count-1 of a clip.</summary>
        internal static MotionClip Excerpt(MotionClip clip, int start, int count)
        {
            int j = clip.Skeleton.JointCount;
            var positions = new double[count * j * 3];
            var rotations = new double[count * j * 4];
            Array.Copy(clip.LocalPositions, start * j * 3, positions, 0, positions.Length);
            Array.Copy(clip.LocalRotations, start * j * 4, rotations, 0, rotations.Length);
            return new MotionClip(clip.Skeleton, count, clip.FrameTime, positions, rotations);
        }

        /// <summary>
        /// Before any work: --preview and --png (the contact sheet's actual path) are writable, not inputs,
        /// and differ from each other and from --out.
        /// </summary>
        internal static void CheckPreviewOutputs(string? previewPath, string? pngPath, string[] otherOutputs, bool force, params string?[] inputs)
        {
            if (pngPath != null && previewPath == null) throw new CliErrors.UsageException($"{pngPath}: --png without --preview; expected --preview OUT.html with it");
            if (previewPath == null) return;
            var taken = new System.Collections.Generic.List<string>();
            foreach (string o in otherOutputs) taken.Add(Path.GetFullPath(o));
            string html = OutputFile.Check(previewPath, force, inputs);
            if (taken.Contains(Path.GetFullPath(html))) throw new CliErrors.UsageException($"{previewPath}: the same file as another output; expected a different path for --preview");
            taken.Add(Path.GetFullPath(html));
            if (pngPath == null) return;
            // The PNG and the SVG written instead when Chromium fails: both checked now, not after the work.
            ContactSheet.CheckOutputs(pngPath, force, taken, inputs);
        }

        /// <summary>Gaps filled → one progress bar ("Baking gaps with the model"), updated synchronously.</summary>
        private sealed class GapProgress : IProgress<int>
        {
            private readonly IProgress<BenchmarkProgress> _bars;
            private readonly int _total;

            public GapProgress(IProgress<BenchmarkProgress> bars, int total)
            {
                _bars = bars;
                _total = total;
            }

            public void Report(int value) => _bars.Report(new BenchmarkProgress("Baking gaps with the model", value, _total));
        }

        private static BakePlan Plan(ClipBaker baker, int frameCount, int[] keys, string input)
        {
            try
            {
                return baker.Plan(frameCount, keys);
            }
            catch (KeyLayoutException e)
            {
                throw new CliErrors.UsageException($"{input}: {e.Message}");
            }
        }

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

        private static void PrintSummary(
            string input, BvhAnimation animation, int[] keys, BakePlan plan, BakeSettings settings, ModelContract contract, IBakeRetargeting seam,
            string outPath, string method, BakeAccuracy model, BakeAccuracy slerp, BenchmarkStatistics? statistics,
            double modelSeconds, double slerpSeconds, double readSeconds, double loadSeconds, double totalSeconds, BakeFeet.Scores skating, bool locked)
        {
            foreach (string warning in plan.Warnings) AnsiConsole.MarkupLine("[yellow]warning:[/] " + Markup.Escape(warning));
            MotionClip motion = animation.Motion;
            string unit = "file units";
            var table = new Table().Border(TableBorder.Rounded)
                .Title($"[bold]{Markup.Escape(Path.GetFileName(input))}[/]: error on the {model.Frames:N0} non-key frames (lower is better)");
            table.AddColumn("Method");
            table.AddColumn(new TableColumn($"Mean joint position error ({unit})").RightAligned());
            table.AddColumn(new TableColumn("L2Q").RightAligned());
            table.AddColumn(new TableColumn(statistics != null ? "L2P" : "L2P (no statistics)").RightAligned());
            table.AddColumn(new TableColumn("Foot skating (leg/s)").RightAligned());
            table.AddColumn(new TableColumn("Bake time (s)").RightAligned());
            AddRow(table, "Model (" + Path.GetFileNameWithoutExtension(contract.Source) + ")", model, modelSeconds, skating.Model);
            AddRow(table, "SLERP", slerp, slerpSeconds, skating.Slerp);
            table.AddRow("Ground truth", "-", "-", "-", BakeFeet.Format(skating.Truth), "-");
            AnsiConsole.Write(table);
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "feet: {0}; foot skating: mean horizontal speed of ankles and toes on the {1:N0} (frame, joint) pairs where the ground truth's are planted (within 3 % of a leg of the ground, under 15 % of a leg per second), in leg lengths per second",
                locked ? "locked (--feet lock: planted feet held still on the filled frames, keys untouched)" : "not locked (--feet off)", skating.Truth.ContactSamples)));

            string policy = settings.ShortContext == ShortContextPolicy.RepeatEarliest ? "repeat the earliest" : "feed what exists";
            string trained = settings.TrainedPastFrames is { } p ? $"trained on {p.Min}..{p.Max} past frames" : "trained past range unknown";
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "{0:N0} frames at {1:0.##} fps, {2} keys ({3}{4}), {5} gaps; model context: up to {6} past frames ({10}), where fewer exist: {7} ({8}); {9}",
                motion.FrameCount, 1.0 / motion.FrameTime, keys.Length, KeySummary(keys), plan.FrameCount < motion.FrameCount ? $"; output frames {keys[0]}..{keys[keys.Length - 1]}" : "",
                plan.Gaps.Count, settings.PastFrames, policy, trained, seam.Description,
                settings.FilledFramesAsContext ? "keys and filled frames" : "key frames only")));
            if (seam is SkeletonRetargeting retargeted) AnsiConsole.MarkupLine(Markup.Escape(KeyLine(retargeted)));
            if (statistics != null) AnsiConsole.MarkupLine(Markup.Escape($"L2P: per-coordinate std of {statistics.Source}, frames where they are in the file (no window normalisation); L2Q: global quaternions, each in the truth's hemisphere"));
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "wrote {0} ({1}); read {2:0.000} s, model load {3:0.000} s, total {4:0.00} s",
                outPath, method == "model" ? "model" : "SLERP", readSeconds, loadSeconds, totalSeconds)));
        }

        /// <summary>How the retargeted output's key frames relate to the input's (one line).</summary>
        internal static string KeyLine(SkeletonRetargeting retargeted) => string.Format(CultureInfo.InvariantCulture,
            "key frames: the input's, copied exactly (mapping them to the model's skeleton and back came within {0:0.###e+0}° of them)", retargeted.KeyRoundTripDegrees);

        private static void AddRow(Table table, string name, BakeAccuracy a, double seconds, FootSkating skating)
        {
            table.AddRow(
                Markup.Escape(name),
                a.MeanPositionError.ToString("0.000", CultureInfo.InvariantCulture),
                a.L2Q.ToString("0.0000", CultureInfo.InvariantCulture),
                double.IsNaN(a.L2P) ? "-" : a.L2P.ToString("0.0000", CultureInfo.InvariantCulture),
                BakeFeet.Format(skating),
                seconds.ToString("0.000", CultureInfo.InvariantCulture));
        }

        private static string KeySummary(int[] keys)
        {
            if (keys.Length <= 6) return string.Join(",", keys);
            return $"{keys[0]},{keys[1]},{keys[2]},…,{keys[keys.Length - 1]}";
        }

        private static ShortContextPolicy? ParsePolicy(string text)
        {
            switch (text)
            {
                case "auto": return null;
                case "feed": return ShortContextPolicy.FeedAvailable;
                case "repeat": return ShortContextPolicy.RepeatEarliest;
                default: throw new CliErrors.UsageException($"inbetween bake: --past-policy '{text}'; expected auto, feed or repeat");
            }
        }

        private static int[] ParseKeys(string text, string input)
        {
            var keys = new List<int>();
            text = KeyListArgument.Text(text);
            foreach (string part in text.Split(','))
            {
                string p = part.Trim();
                if (!int.TryParse(p, NumberStyles.None, CultureInfo.InvariantCulture, out int k))
                {
                    throw new CliErrors.UsageException($"{input}: --keys '{text}' has '{p}'; expected comma-separated frame indices such as 0,12,40");
                }

                keys.Add(k);
            }

            return keys.ToArray();
        }
    }
}
