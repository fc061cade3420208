using System;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text;
using Spectre.Console;
using DeltaInterpolator.Cli.Retargeting;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.OnnxRuntime;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>inbetween retarget IN.bvh --to model|OTHER.bvh --out OUT.bvh</c>: moves a clip onto the model's
    /// skeleton (read from the model file's contract, resampled to the model's frame rate) or onto another
    /// BVH file's skeleton (through the model's skeleton; the other file's frame rate is not imposed: the
    /// input's is kept unless <c>--fps</c> says otherwise).
    /// </summary>
    public sealed class RetargetVerb : ICliVerb
    {
        /// <summary>The model whose skeleton <c>--to model</c> means when <c>--model</c> is not given.</summary>
        internal const string DefaultModel = ShippedModels.Default;

        private readonly Argument<string> _input = new Argument<string>("IN")
        {
            Description = "The BVH file to retarget (any humanoid: " + BuiltInMapNames.List + " joint names, or --map)",
        };

        private readonly Option<string> _to = new Option<string>("--to")
        {
            Description = "'model' for the model's skeleton (LaFAN1's 22 joints, at the model's frame rate), or a BVH file whose skeleton receives the motion",
            HelpName = "model|OTHER.bvh",
            Required = true,
        };

        private readonly Option<string> _out = new Option<string>("--out")
        {
            Description = "The BVH file to write (refused if it exists, unless --force, or if it is an input)",
            HelpName = "OUT.bvh",
            Required = true,
        };

        private readonly Option<string?> _map = new Option<string?>("--map")
        {
            Description = "A JSON joint map {\"ModelJoint\": \"sourceJoint\" or [\"chain\", \"of\", \"joints\"], …} for names the built-in maps (" + BuiltInMapNames.List + ") miss; joints it leaves out take the built-in names, null: a joint the rig lacks, made up (Documentation~/retargeting.md)",
            HelpName = "MAP.json",
        };

        private readonly Option<int?> _referenceFrame = new Option<int?>("--reference-frame")
        {
            Description = "The input frame that is its reference pose (e.g. 0 for a CMU file's T-pose); default: the model's T-pose for LaFAN1 joint names, otherwise the zero pose (all rotations 0)",
            HelpName = "K",
        };

        private readonly Option<string> _up = UpAxisArgument.Create();
        private readonly Option<bool> _acceptReferencePose = ReferencePoseArgument.Create();

        private readonly Option<int?> _targetReferenceFrame = new Option<int?>("--target-reference-frame")
        {
            Description = "With --to OTHER.bvh: the frame of OTHER that is its reference pose and supplies its unmapped joints; default as for --reference-frame",
            HelpName = "K",
        };

        private readonly Option<double?> _fps = new Option<double?>("--fps")
        {
            Description = "Output frame rate; default: the model's (30) with --to model, the input's with --to OTHER.bvh",
            HelpName = "F",
        };

        private readonly Option<double?> _inputFps = new Option<double?>("--input-fps")
        {
            Description = "The input's true frame rate when its header is wrong (CMU subjects 60 and 61 are 60 fps but say 120)",
            HelpName = "F",
        };

        private readonly Option<int?> _fromFrame = new Option<int?>("--from-frame")
        {
            Description = "Drop the input frames before K (a T-pose, conversion artefacts); the reference frame may still be one of them",
            HelpName = "K",
        };

        private readonly Option<double?> _scale = new Option<double?>("--scale")
        {
            Description = "Model units per input unit for the root's position; default: the ratio of leg lengths (root height above the lowest joint in each reference pose), which also converts units",
            HelpName = "S",
        };

        private readonly Option<string?> _model = new Option<string?>("--model")
        {
            Description = "The model whose skeleton and frame rate are used (default " + DefaultModel + ")",
            HelpName = "FILE.onnx",
        };

        private readonly OutputOptions _output = new OutputOptions();

        /// <inheritdoc />
        public Command CreateCommand()
        {
            var command = new Command(
                "retarget",
                "Move motion onto the model's skeleton (or another BVH file's), matching every mapped bone's world direction,\n" +
                "scaling the root by leg length and resampling to the model's frame rate.\n" +
                "Joints are matched by name (built-in " + BuiltInMapNames.List + " tables, or --map;\n" +
                "Documentation~/retargeting.md has the model's 22 joints, the map format and what each refusal means);\n" +
                "a skeleton missing joints the model needs is refused with their names (exit status 2).\n" +
                "Example:\n  inbetween retarget Samples~/Demo/cmu_09_12_walk_navigate.bvh --to model --reference-frame 0 --from-frame 1 --out out/walk_on_model.bvh");
            command.Arguments.Add(_input);
            command.Options.Add(_to);
            command.Options.Add(_out);
            command.Options.Add(_map);
            command.Options.Add(_referenceFrame);
            command.Options.Add(_up);
            command.Options.Add(_acceptReferencePose);
            command.Options.Add(_targetReferenceFrame);
            command.Options.Add(_fps);
            command.Options.Add(_inputFps);
            command.Options.Add(_fromFrame);
            command.Options.Add(_scale);
            command.Options.Add(_model);
            _output.AddTo(command);
            command.SetAction(parse => CliErrors.Guard(() => Run(parse)));
            return command;
        }

        private int Run(ParseResult parse)
        {
            var clock = Stopwatch.StartNew();
            string input = parse.GetValue(_input)!;
            string to = parse.GetValue(_to)!;
            string output = parse.GetValue(_out)!;
            string? mapPath = parse.GetValue(_map);
            string modelPath = parse.GetValue(_model) ?? ShippedModels.Find(DefaultModel);
            bool toModel = string.Equals(to, "model", StringComparison.Ordinal);
            double? fps = parse.GetValue(_fps);
            if (fps.HasValue && !(fps.Value > 0 && fps.Value <= 10000))
            {
                throw new CliErrors.UsageException($"inbetween retarget: --fps {fps.Value.ToString(CultureInfo.InvariantCulture)}; expected a frame rate above 0");
            }

            double? inputFps = parse.GetValue(_inputFps);
            if (inputFps.HasValue && !(inputFps.Value >= 1 && inputFps.Value <= 1000))
            {
                throw new CliErrors.UsageException($"inbetween retarget: --input-fps {inputFps.Value.ToString(CultureInfo.InvariantCulture)}; expected a frame rate from 1 to 1000");
            }

            int? fromFrame = parse.GetValue(_fromFrame);
            double? scale = parse.GetValue(_scale);
            if (scale.HasValue && !(scale.Value > 0 && !double.IsInfinity(scale.Value)))
            {
                throw new CliErrors.UsageException($"inbetween retarget: --scale {scale.Value.ToString(CultureInfo.InvariantCulture)}; expected a positive number of model units per input unit");
            }

            UpAxis up = UpAxisArgument.Parse(parse.GetValue(_up), "retarget");
            RequireFile(input, "the BVH file to retarget");
            if (!toModel) RequireFile(to, "'model' or a BVH file whose skeleton receives the motion");
            if (mapPath != null) RequireFile(mapPath, "a JSON joint map");
            RequireFile(modelPath, "the model file whose skeleton is the target (--model)");
            OutputFile.Check(output, parse.GetValue(_output.Force), input, toModel ? null : to, mapPath, modelPath);

            BvhAnimation source = BvhReader.Read(input);
            MotionChecks.RequireFrame(source.Motion, parse.GetValue(_referenceFrame), "--reference-frame", input);
            MotionChecks.RequireFrame(source.Motion, fromFrame, "--from-frame", input, spare: 1);
            ModelContract contract;
            using (Inbetweener model = InbetweenerLoader.Load(new OnnxModelFiles(modelPath), LazyGraphs.None)) contract = model.Contract;
            JointMap? userMap = mapPath == null ? null : JointMap.Load(mapPath, JointMap.Detect(source.Skeleton, contract.Skeleton));
            if (userMap != null) MapWarnings.UnknownTargets(userMap, contract.Skeleton, mapPath!);
            var request = new RetargetRequest
            {
                ReferenceFrame = parse.GetValue(_referenceFrame), FromFrame = fromFrame ?? 0, InputFps = inputFps, OutputFps = fps, Scale = scale,
                Map = userMap, TargetReferenceFrame = parse.GetValue(_targetReferenceFrame), Up = up,
                AcceptReferencePose = parse.GetValue(_acceptReferencePose),
            };
            RetargetResult retargeted;
            BvhAnimation result;
            if (toModel)
            {
                retargeted = MotionRetargeting.ToModel(source.Motion, input, contract, request);
                result = BvhAnimation.ForSkeleton(retargeted.Motion, output);
            }
            else
            {
                BvhAnimation other = BvhReader.Read(to);
                MotionChecks.RequireFrame(other.Motion, request.TargetReferenceFrame, "--target-reference-frame", to);
                retargeted = MotionRetargeting.ToRig(source.Motion, input, other.Motion, to, contract, request);
                result = new BvhAnimation(retargeted.Motion, other.JointChannels, other.EndSites, output);
            }

            OutputFile.Write(output, stream =>
            {
                using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
                BvhWriter.Write(result, writer);
            });

            RetargetSummary.Print(input, source, retargeted.ToModel, retargeted.FromModel, request.ReferenceFrame, scale.HasValue, fromFrame, inputFps, result, output, toModel ? contract.Name : to, clock.Elapsed.TotalSeconds);
            if (retargeted.AcceptedReference != null) AnsiConsole.MarkupLine(Markup.Escape($"warning: {input}: {retargeted.AcceptedReference}"));
            return 0;
        }

        private static void RequireFile(string path, string what)
        {
            InputFile.Check(path, what); // a folder, a named pipe or a device is refused as such, before it is opened
        }
    }
}
