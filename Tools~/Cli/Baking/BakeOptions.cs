using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Cli.Baking
{
    /// <summary><c>bake</c>'s arguments and options: one declaration each, and <see cref="Parse"/>, which checks them all before any work.</summary>
    internal sealed class BakeOptions
    {
        public const string ShippedModel = ShippedModels.Default;
        public const string DefaultStats = "../shared/data/lafan1/train_stats_official.json";

        public readonly Argument<string> _input = new Argument<string>("IN.bvh")
        {
            Description = "BVH file of a humanoid: on the model's skeleton at its rate (LaFAN1, 30 fps) it is baked as is, any other (e.g. CMU at 120 fps) is retargeted onto the model's skeleton and rate and the results mapped back; its frames are the keys' source and the ground truth.",
        };

        public readonly Option<string?> _keys = new Option<string?>("--keys")
        {
            Description = "Key frame indices of IN.bvh, increasing, comma-separated (at least two), or @FILE for a file of them (commas, spaces or lines). The output spans the first to the last key.",
            HelpName = "F,F,...",
        };

        public readonly Option<string?> _every = new Option<string?>("--every")
        {
            Description = "A key every K: input frames by default (60), model frames with 'mf' (15mf) or seconds with 's' (0.5s); keys at equal times from the first usable frame, the file's last frame a key, and the last gap kept within the model's trained minimum of missing frames (the key before it moved to the middle of the last two gaps, or dropped). The spacing is printed in all three units.",
            HelpName = "K|Kmf|Xs",
        };

        public readonly Option<string> _method = new Option<string>("--method")
        {
            Description = "Which method's result OUT.bvh holds: the neural model or SLERP (both are always scored).",
            HelpName = "model|slerp",
            DefaultValueFactory = _ => "model",
        };

        public readonly Option<string?> _model = new Option<string?>("--model")
        {
            Description = "Exported model (NAME.onnx). Default: the shipped " + ShippedModel + ".",
            HelpName = "FILE.onnx",
        };

        public readonly Option<string> _pastPolicy = new Option<string>("--past-policy")
        {
            Description = "What the model gets where fewer past frames exist than it wants (a clip's first gaps): 'auto' from the model's trained past range (fixed 10 → repeat, from 1 → feed), 'feed' the frames that exist, 'repeat' the earliest repeated.",
            HelpName = "auto|feed|repeat",
            DefaultValueFactory = _ => "auto",
        };

        public readonly Option<string> _context = new Option<string>("--context")
        {
            Description = "Past context of a gap: 'filled' = key frames and frames already filled (default), 'keys' = key frames only (the key before the gap, laid out by --past-policy).",
            HelpName = "filled|keys",
            DefaultValueFactory = _ => "filled",
        };

        public readonly Option<string> _out = new Option<string>("--out")
        {
            Description = "Output BVH file (same joints and channels as IN.bvh).",
            HelpName = "OUT.bvh",
            Required = true,
        };

        public readonly OutputOptions _output = new OutputOptions();

        public readonly Option<int?> _referenceFrame = new Option<int?>("--reference-frame")
        {
            Description = "For input on another skeleton (retargeted): the input frame that is its reference pose (e.g. 0 for a CMU file's T-pose); default: its default pose (see 'retarget --help').",
            HelpName = "K",
        };

        public readonly Option<string> _up = UpAxisArgument.Create();

        public readonly Option<bool> _acceptReferencePose = ReferencePoseArgument.Create();

        public readonly Option<string?> _map = new Option<string?>("--map")
        {
            Description = "A JSON joint map {\"ModelJoint\": \"sourceJoint\" or [\"chain\"] or null, …} for names the built-in maps miss (the format 'retarget --map' reads; null or omitted: a joint the rig lacks, synthesized).",
            HelpName = "MAP.json",
        };

        public readonly Option<double?> _inputFps = new Option<double?>("--input-fps")
        {
            Description = "The input's true frame rate when its header is wrong (CMU subjects 60 and 61: 60 fps, the header says 120); the output says it too.",
            HelpName = "F",
        };

        public readonly Option<int?> _fromFrame = new Option<int?>("--from-frame")
        {
            Description = "The first frame that may be a key (frames before it — a T-pose, conversion artefacts — are never keys and never scored); --every counts from it.",
            HelpName = "K",
        };

        public readonly Option<string> _feet = new Option<string>("--feet")
        {
            Description = "Foot locking of both methods' filled frames, on the skeleton written (a retargeted input's own, after mapping back): 'lock' holds planted feet still (two-bone IK, key frames untouched), 'off' leaves them as filled (default: lock). Foot skating is reported either way.",
            HelpName = "lock|off",
            // On by default: with the default (CMU) model locking keeps the position error within 2 % of 'off' on every
            // measured bake (demo clip −0.4 %, worst +1.1 %) and cuts the demo clip's foot skating 0.265 → 0.148 leg/s.
            DefaultValueFactory = _ => "lock",
        };

        public readonly Option<string?> _json = new Option<string?>("--json")
        {
            Description = "Also write each method's scores as JSON: mean joint position error (file units and ÷ leg length), L2Q, L2P, non-key frames (what 'score' adds up over folders).",
            HelpName = "OUT.json",
        };

        public readonly Option<string?> _preview = new Option<string?>("--preview")
        {
            Description = "Also write a self-contained HTML player of ground truth, SLERP and model over the baked frames (input's skeleton).",
            HelpName = "OUT.html",
        };

        public readonly Option<string?> _png = new Option<string?>("--png")
        {
            Description = "With --preview: also a PNG contact sheet (headless Chromium; without it, an SVG beside it instead).",
            HelpName = "OUT.png",
        };

        public readonly Option<string?> _stats = new Option<string?>("--stats")
        {
            Description = "Statistics JSON for L2P on LaFAN1-skeleton files. Default: " + DefaultStats + " when present.",
            HelpName = "FILE",
        };

        public readonly Option<int> _threads = new Option<int>("--threads")
        {
            Description = "ONNX Runtime intra-op threads. At most the processors of this machine (" + Verbs.ModelOptions.MaximumThreads + ").",
            HelpName = "N",
            DefaultValueFactory = _ => 1,
        };

        /// <summary>Adds every argument and option to <paramref name="command"/>.</summary>
        public void AddTo(Command command)
        {
            command.Arguments.Add(_input);
            foreach (Option o in new Option[] { _keys, _every, _method, _model, _pastPolicy, _context, _out }) command.Options.Add(o);
            _output.AddTo(command);
            foreach (Option o in new Option[] { _referenceFrame, _up, _acceptReferencePose, _map, _inputFps, _fromFrame, _feet, _json, _preview, _png, _stats, _threads }) command.Options.Add(o);
        }

        /// <summary>The request, every value checked and every output checked writable and distinct from the inputs and each other.</summary>
        public BakeRequest Parse(ParseResult parse)
        {
            var r = new BakeRequest
            {
                Input = parse.GetValue(_input)!,
                Every = EveryArgument.Parse(parse.GetValue(_every), "bake"),
                Method = parse.GetValue(_method)!,
                OutPath = parse.GetValue(_out)!,
                Force = parse.GetValue(_output.Force),
                Threads = parse.GetValue(_threads),
                Policy = ParsePolicy(parse.GetValue(_pastPolicy)!),
                Feet = BakeFeet.Parse(parse.GetValue(_feet)!),
                ReferenceFrame = parse.GetValue(_referenceFrame),
                Up = UpAxisArgument.Parse(parse.GetValue(_up), "bake"),
                AcceptReferencePose = parse.GetValue(_acceptReferencePose),
            };
            string? keysText = parse.GetValue(_keys);
            if ((keysText == null) == (r.Every == null))
            {
                throw new CliErrors.UsageException("inbetween bake: " + (keysText == null ? "neither --keys nor --every given" : "both --keys and --every given") + "; expected exactly one of them");
            }

            if (r.Method != "model" && r.Method != "slerp") throw new CliErrors.UsageException($"inbetween bake: --method '{r.Method}'; expected model or slerp");
            string context = parse.GetValue(_context)!;
            if (context != "filled" && context != "keys") throw new CliErrors.UsageException($"inbetween bake: --context '{context}'; expected filled or keys");
            r.FilledContext = context == "filled";
            if (r.Threads < 1) throw new CliErrors.UsageException($"inbetween bake: --threads {r.Threads}; expected 1 or more");
            if (r.Threads > Verbs.ModelOptions.MaximumThreads)
            {
                // As speed and benchmark: 500 threads took 19 s, 2147483647 failed as std::bad_alloc blamed on the model.
                throw new CliErrors.UsageException($"inbetween bake: --threads {r.Threads} is more than the {Verbs.ModelOptions.MaximumThreads} processors of this machine; expected at most {Verbs.ModelOptions.MaximumThreads} (more threads only compete for the same cores)");
            }

            InputFile.Check(r.Input, "a .bvh file");
            r.ModelPath = parse.GetValue(_model) ?? ShippedModels.Find(ShippedModel);
            InputFile.Check(r.ModelPath, $"an exported model (NAME.onnx), e.g. {ShippedModel}");
            string? statsGiven = parse.GetValue(_stats);
            if (statsGiven != null) InputFile.Check(statsGiven, $"a statistics JSON such as {DefaultStats}");
            r.StatsGiven = statsGiven != null;
            r.StatsPath = statsGiven ?? (File.Exists(DefaultStats) ? DefaultStats : null);
            r.MapPath = parse.GetValue(_map);
            if (r.MapPath != null) InputFile.Check(r.MapPath, "a JSON joint map"); // a folder, a named pipe or a device is refused as such
            r.InputFps = parse.GetValue(_inputFps);
            if (r.InputFps.HasValue && !(r.InputFps.Value >= 1 && r.InputFps.Value <= 1000))
            {
                throw new CliErrors.UsageException($"inbetween bake: --input-fps {r.InputFps.Value.ToString(CultureInfo.InvariantCulture)}; expected a frame rate from 1 to 1000");
            }

            r.FromFrame = parse.GetValue(_fromFrame) ?? 0;
            if (r.FromFrame < 0) throw new CliErrors.UsageException($"inbetween bake: --from-frame {r.FromFrame}; expected a frame index from 0");
            if (keysText != null) r.Keys = ParseKeys(keysText, r.Input);

            // Before any work: the outputs must be writable and must not replace an input or each other. A key
            // list file (--keys @FILE) is read like the others, so --force never lets an output replace it.
            string?[] inputs = { r.Input, r.ModelPath, r.StatsPath, r.MapPath, keysText == null ? null : KeyListArgument.FilePath(keysText) };
            r.OutFull = OutputFile.Check(r.OutPath, r.Force, inputs);
            r.JsonPath = parse.GetValue(_json);
            r.JsonFull = r.JsonPath == null ? null : OutputFile.Check(r.JsonPath, r.Force, inputs);
            if (r.JsonFull != null && string.Equals(r.JsonFull, r.OutFull, StringComparison.Ordinal)) throw new CliErrors.UsageException($"{r.JsonPath}: the same file as --out; expected a different path for --json");
            r.PreviewPath = parse.GetValue(_preview);
            r.PngPath = parse.GetValue(_png);
            BakePreview.CheckOutputs(r.PreviewPath, r.PngPath, r.JsonFull == null ? new[] { r.OutFull } : new[] { r.OutFull, r.JsonFull }, r.Force, inputs);
            return r;
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
