using System;
using System.Collections.Generic;
using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.OnnxRuntime;
using Spectre.Console;

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
            Description = "The BVH file to retarget (any humanoid: LaFAN1, CMU, Mixamo or Unity names, or --map)",
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
            Description = "A JSON joint map {\"ModelJoint\": \"sourceJoint\" or [\"chain\", \"of\", \"joints\"], …} for names the built-in maps (LaFAN1, CMU, Mixamo, Unity) miss",
            HelpName = "MAP.json",
        };

        private readonly Option<int?> _referenceFrame = new Option<int?>("--reference-frame")
        {
            Description = "The input frame that is its reference pose (e.g. 0 for a CMU file's T-pose); default: the model's T-pose for LaFAN1 joint names, otherwise the zero pose (all rotations 0)",
            HelpName = "K",
        };

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
                "Joints are matched by name (built-in LaFAN1, CMU, Mixamo and Unity HumanBodyBones tables, or --map);\n" +
                "a skeleton missing joints the model needs is refused with their names (exit status 2).\n" +
                "Example:\n  inbetween retarget Samples~/Demo/cmu_09_12_walk_navigate.bvh --to model --reference-frame 0 --from-frame 1 --out out/walk_on_model.bvh");
            command.Arguments.Add(_input);
            command.Options.Add(_to);
            command.Options.Add(_out);
            command.Options.Add(_map);
            command.Options.Add(_referenceFrame);
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

            RequireFile(input, "the BVH file to retarget");
            if (!toModel) RequireFile(to, "'model' or a BVH file whose skeleton receives the motion");
            if (mapPath != null) RequireFile(mapPath, "a JSON joint map");
            RequireFile(modelPath, "the model file whose skeleton is the target (--model)");
            OutputFile.Check(output, parse.GetValue(_output.Force), input, toModel ? null : to, mapPath, modelPath);

            BvhAnimation source = BvhReader.Read(input);
            ModelContract contract = ReadContract(modelPath);
            ReferencePose sourceReference = Reference(source, parse.GetValue(_referenceFrame), "--reference-frame", input);
            ReferencePose modelReference = ReferencePose.ModelTPose(contract.Skeleton);
            JointMap? userMap = mapPath == null ? null : JointMap.Load(mapPath, JointMap.Detect(source.Skeleton, contract.Skeleton));
            if (userMap != null) MapWarnings.UnknownTargets(userMap, contract.Skeleton, mapPath!);
            SkeletonMap toModelMap = Map(sourceReference, modelReference, userMap, input, scale);

            MotionClip sourceMotion = Trim(source.Motion, fromFrame, inputFps, input);
            MotionClip onModel = toModelMap.ToTarget(sourceMotion);
            BvhAnimation result;
            SkeletonMap? fromModelMap = null;
            if (toModel)
            {
                double frameTime = 1.0 / (fps ?? contract.FramesPerSecond);
                // BVH files round their frame time (LaFAN1: 0.033333): within 0.01 % it is the same rate, kept as written.
                MotionClip resampled = Math.Abs(frameTime - onModel.FrameTime) > 1e-4 * frameTime ? MotionResampler.Resample(onModel, frameTime, input) : onModel;
                result = BvhAnimation.ForSkeleton(resampled, output);
            }
            else
            {
                BvhAnimation other = BvhReader.Read(to);
                ReferencePose otherReference = Reference(other, parse.GetValue(_targetReferenceFrame), "--target-reference-frame", to);
                fromModelMap = Map(otherReference, modelReference, userMap, to);
                MotionClip otherPose = OneFrame(other.Skeleton, otherReference, source.Motion.FrameTime);
                MotionClip onOther = fromModelMap.ToSource(onModel, otherPose);
                if (inputFps.HasValue && !fps.HasValue) onOther = MotionResampler.Resample(onOther, source.Motion.FrameTime, input);
                if (fps.HasValue) onOther = MotionResampler.Resample(onOther, 1.0 / fps.Value, input);
                result = new BvhAnimation(onOther, other.JointChannels, other.EndSites, output);
            }

            OutputFile.Write(output, stream =>
            {
                using var writer = new StreamWriter(stream, new UTF8Encoding(false), 1 << 16, leaveOpen: true);
                BvhWriter.Write(result, writer);
            });

            PrintSummary(input, source, toModelMap, fromModelMap, parse.GetValue(_referenceFrame), scale.HasValue, fromFrame, inputFps, result, output, toModel ? contract.Name : to, clock.Elapsed.TotalSeconds);
            return 0;
        }

        /// <summary>The input's frames from <paramref name="fromFrame"/> on, at its true frame rate.</summary>
        private static MotionClip Trim(MotionClip motion, int? fromFrame, double? inputFps, string path)
        {
            int first = fromFrame ?? 0;
            if (first < 0 || first > motion.FrameCount - 2)
            {
                throw new CliErrors.UsageException($"{path}: --from-frame {first} leaves fewer than two of the file's {motion.FrameCount} frames; expected 0 to {Math.Max(0, motion.FrameCount - 2)}");
            }

            double frameTime = inputFps.HasValue ? 1.0 / inputFps.Value : motion.FrameTime;
            if (first == 0 && !inputFps.HasValue) return motion;
            int j = motion.Skeleton.JointCount, n = motion.FrameCount - first;
            var positions = new double[n * j * 3];
            var rotations = new double[n * j * 4];
            Array.Copy(motion.LocalPositions, motion.PositionIndex(first, 0), positions, 0, positions.Length);
            Array.Copy(motion.LocalRotations, motion.RotationIndex(first, 0), rotations, 0, rotations.Length);
            return new MotionClip(motion.Skeleton, n, frameTime, positions, rotations);
        }

        private static void RequireFile(string path, string what)
        {
            InputFile.Check(path, what); // a folder, a named pipe or a device is refused as such, before it is opened
        }

        private static ModelContract ReadContract(string modelPath)
        {
            try
            {
                using OnnxRuntimeBackend backend = OnnxRuntimeBackend.Load(modelPath);
                return ModelContract.Read(backend.Description, ModelGraphKind.Whole);
            }
            catch (ModelContractException e)
            {
                throw new CliErrors.UsageException(e.Message);
            }
        }

        private static ReferencePose Reference(BvhAnimation animation, int? frame, string option, string path)
        {
            if (frame == null) return ReferencePose.Default(animation.Skeleton);
            int count = animation.Motion.FrameCount;
            if (frame.Value < 0 || frame.Value >= count)
            {
                throw new CliErrors.UsageException($"{path}: {option} {frame.Value} is not a frame of the file; expected 0 to {count - 1}");
            }

            return ReferencePose.FromFrame(animation.Motion, frame.Value);
        }

        private static SkeletonMap Map(ReferencePose source, ReferencePose model, JointMap? userMap, string path, double? scale = null)
        {
            try
            {
                return SkeletonMap.Create(source, model, userMap, path, scale);
            }
            catch (JointMapException e)
            {
                throw new CliErrors.UsageException(e.Message);
            }
        }

        private static MotionClip OneFrame(Skeleton skeleton, ReferencePose pose, double frameTime)
        {
            int j = skeleton.JointCount;
            var positions = new double[3 * j];
            skeleton.OffsetSpan.CopyTo(positions);
            pose.RootPosition.Write(positions, 0);
            var rotations = new double[4 * j];
            for (int i = 0; i < rotations.Length; i++) rotations[i] = pose.LocalRotations[i];
            return new MotionClip(skeleton, 1, frameTime, positions, rotations);
        }

        private static void PrintSummary(string input, BvhAnimation source, SkeletonMap toModel, SkeletonMap? fromModel, int? referenceFrame, bool scaleGiven,
            int? fromFrame, double? inputFps, BvhAnimation result, string output, string target, double seconds)
        {
            var table = new Table().Border(TableBorder.Rounded).HideHeaders();
            table.AddColumn("");
            table.AddColumn("");
            MotionClip inClip = source.Motion, outClip = result.Motion;
            table.AddRow("Input", Markup.Escape($"{input}: {source.Skeleton.JointCount} joints, {inClip.FrameCount} frames at {Fps(inClip.FrameTime)} fps"));
            table.AddRow("Reference pose", referenceFrame.HasValue ? $"frame {referenceFrame.Value}"
                : HasLafanNames(source.Skeleton) ? "the model's T-pose (LaFAN1 joint names and axes)" : "zero pose (all rotations 0)");
            table.AddRow("Joint map", Markup.Escape($"'{toModel.Map.Name}': {toModel.Target.JointCount} model joints from {Mapped(toModel)}"));
            table.AddRow("Made up (synthesized)", Markup.Escape(toModel.SynthesizedJoints.Count == 0 ? "none"
                : string.Join(", ", toModel.SynthesizedJoints) + ": the input lacks them; each is a rigid child of its parent at the model's T-pose offset"));
            table.AddRow(fromModel == null ? "Unmapped input joints" : "Unmapped (from OTHER's reference)", Markup.Escape(toModel.UnmappedSourceJoints.Count == 0 ? "none" : MapWarnings.NameList(toModel.UnmappedSourceJoints)));
            table.AddRow("Root scale", Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "× {0:0.#####} {3}(model leg {1:0.##} ÷ input leg {2:0.###}: root height above the lowest joint in each reference pose)",
                toModel.RootScale, toModel.TargetLegLength, toModel.SourceLegLength, scaleGiven ? "as given by --scale " : "")));
            if (fromModel != null)
            {
                table.AddRow("Target", Markup.Escape($"{target}: {fromModel.Source.JointCount} joints, map '{fromModel.Map.Name}', root × {(toModel.RootScale / fromModel.RootScale).ToString("0.#####", CultureInfo.InvariantCulture)}"));
            }
            else
            {
                table.AddRow("Target", Markup.Escape($"model '{target}' skeleton ({toModel.Target.JointCount} joints)"));
            }

            table.AddRow("Frames", Markup.Escape($"{inClip.FrameCount} at {Fps(inClip.FrameTime)} fps{(fromFrame > 0 ? $" (from frame {fromFrame})" : "")}{(inputFps.HasValue ? $" (read as {Fps(1 / inputFps.Value)} fps)" : "")} → {outClip.FrameCount} at {Fps(outClip.FrameTime)} fps"));
            table.AddRow("Wrote", Markup.Escape($"{output} ({seconds.ToString("0.00", CultureInfo.InvariantCulture)} s)"));
            AnsiConsole.Write(table);
        }

        private static bool HasLafanNames(Skeleton skeleton)
        {
            foreach (string name in JointMap.Lafan1.TargetJoints) if (skeleton.IndexOf(name) < 0) return false;
            return true;
        }

        private static string Mapped(SkeletonMap map)
        {
            var parts = new List<string>();
            for (int j = 0; j < map.Target.JointCount; j++)
            {
                string t = map.Target.Names[j];
                if (map.IsSynthesized(j)) continue;
                string s = string.Join("+", map.Map.SourceChain(t)!);
                if (!string.Equals(s, t, StringComparison.Ordinal)) parts.Add(s + "→" + t);
            }

            return parts.Count == 0 ? "joints of the same names" : "joints of the same names except " + string.Join(", ", parts);
        }

        private static string Fps(double frameTime) => (1.0 / frameTime).ToString("0.##", CultureInfo.InvariantCulture);
    }
}
