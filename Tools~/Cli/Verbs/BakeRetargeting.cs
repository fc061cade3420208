using System;
using System.Globalization;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// The seam between the input file and the model's skeleton and frame rate, before and after
    /// <c>bake</c>: <see cref="ToModel"/> turns the input into motion on the model's skeleton at the
    /// model's rate (with the keys mapped onto it), <see cref="FromModel"/> turns the baked motion back
    /// onto the input's skeleton and rate. <see cref="SameSkeleton"/> for input already on the model's skeleton at its
    /// rate, <see cref="SkeletonRetargeting"/> for any other humanoid (Core.Retargeting's skeleton map
    /// plus resampling).
    /// </summary>
    internal interface IBakeRetargeting
    {
        /// <summary>One line for the summary, e.g. "input on the model's skeleton (no retargeting)".</summary>
        string Description { get; }

        /// <summary>
        /// The input motion on the model's skeleton at the model's frame rate, <see cref="KeysToModel"/>'s
        /// frames holding the input's key poses.
        /// </summary>
        MotionClip ToModel(BvhAnimation input, int[] inputKeys);

        /// <summary>Input frame indices of keys → frame indices of <see cref="ToModel"/>'s clip.</summary>
        int[] KeysToModel(int[] inputKeys);

        /// <summary>
        /// The baked clip (model skeleton and rate, frames of the first to the last model key) → the input's
        /// skeleton and rate, spanning input frames inputKeys[0]..inputKeys[last], key frames equal to the input's.
        /// </summary>
        MotionClip FromModel(MotionClip baked, BvhAnimation input, int[] inputKeys);
    }

    /// <summary>The identity seam: the input is on the model's skeleton (same joints, same parents) at the model's frame rate.</summary>
    internal sealed class SameSkeleton : IBakeRetargeting
    {
        private readonly ModelContract _contract;
        private readonly string _inputPath;

        public SameSkeleton(ModelContract contract, string inputPath)
        {
            _contract = contract;
            _inputPath = inputPath;
        }

        public string Description => "input on the model's skeleton at its frame rate (no retargeting)";

        /// <summary>Checks the skeleton and the frame rate (the checks a retargeting step would replace).</summary>
        /// <exception cref="ModelContractException">Another skeleton.</exception>
        /// <exception cref="CliErrors.UsageException">Another frame rate.</exception>
        public void Check(BvhAnimation input)
        {
            _contract.CheckSkeleton(input.Skeleton, _inputPath);
            double fps = 1.0 / input.Motion.FrameTime;
            double modelFps = _contract.FramesPerSecond;
            if (Math.Abs(fps - modelFps) > 1e-3 * modelFps)
            {
                throw new CliErrors.UsageException(string.Format(CultureInfo.InvariantCulture,
                    "{0}: frame time {1:0.######} s is {2:0.##} fps; expected the model's {3:0.##} fps (resampling is not supported yet: resample the file first)",
                    _inputPath, input.Motion.FrameTime, fps, modelFps));
            }
        }

        public MotionClip ToModel(BvhAnimation input, int[] inputKeys) => input.Motion;

        public int[] KeysToModel(int[] inputKeys) => inputKeys;

        public MotionClip FromModel(MotionClip baked, BvhAnimation input, int[] inputKeys) => baked;
    }
}
