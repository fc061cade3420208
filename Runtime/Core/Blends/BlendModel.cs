using System;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// The model a track's blends are baked with and how a character reaches it: the network (not owned), its
    /// contract, the joint map and the reference-pose tolerance the component uses. Two blend models are the same
    /// model for <see cref="BlendCache"/> when they hold the same network object and the same map.
    /// </summary>
    public sealed class BlendModel
    {
        /// <summary>A blend model.</summary>
        /// <param name="contract">The network's contract (skeleton, frame rate, trained ranges).</param>
        /// <param name="network">What fills a blend: the loaded model (or anything that stands in for it).</param>
        /// <param name="jointMap">Model joint → bone chains; null: the built-in map that finds the most bones.</param>
        /// <param name="maxBoneDeviationDegrees">How far a mapped bone of the reference pose may point from the model's T-pose (&gt; 0).</param>
        public BlendModel(ModelContract contract, IInbetweener network, JointMap? jointMap = null, double maxBoneDeviationDegrees = CharacterRig.DefaultMaxBoneDeviationDegrees)
        {
            Contract = contract ?? throw new ArgumentNullException(nameof(contract));
            Network = network ?? throw new ArgumentNullException(nameof(network));
            if (!(maxBoneDeviationDegrees > 0) || maxBoneDeviationDegrees > 180)
            {
                throw new ArgumentOutOfRangeException(nameof(maxBoneDeviationDegrees), maxBoneDeviationDegrees, "expected an angle above 0 and at most 180 degrees");
            }

            JointMap = jointMap;
            MaxBoneDeviationDegrees = maxBoneDeviationDegrees;
            Settings = BakeSettings.ForModel(contract);
        }

        /// <summary>The network's contract.</summary>
        public ModelContract Contract { get; }

        /// <summary>What fills a blend.</summary>
        public IInbetweener Network { get; }

        /// <summary>The joint map, or null for the built-in one that finds the most bones.</summary>
        public JointMap? JointMap { get; }

        /// <summary>Reference-pose tolerance of the map.</summary>
        public double MaxBoneDeviationDegrees { get; }

        /// <summary>Past frames, short-context policy, trained ranges: the bake's, from the contract.</summary>
        public BakeSettings Settings { get; }

        /// <summary>Past frames of history fed before a blend (the model's trained maximum).</summary>
        public int PastFrames => Settings.PastFrames;

        /// <summary>Missing frames n of a span of <paramref name="seconds"/>: one model frame per 1/fps, the span's two ends being keys.</summary>
        public int MissingFrames(double seconds) => (int)Math.Round(seconds * Contract.FramesPerSecond, MidpointRounding.AwayFromZero) - 1;

        /// <summary>Why the model cannot fill <paramref name="missing"/> frames (outside its trained range, or beyond its graph), or null when it can.</summary>
        public string? OutsideTrainedRange(int missing)
        {
            if (missing < 1) return $"{missing + 1} model frame(s) long, shorter than one missing frame at {Contract.FramesPerSecond:0.##} fps";
            (int min, int max) = Contract.TrainingMissingFrames;
            if (max >= 1 && (missing < min || missing > max)) return $"{missing} missing frames, outside the {min}..{max} {Contract.Source} was trained on";
            if (missing + 1 > Settings.MaxFrameIndex) return $"{missing} missing frames, more than {Contract.Source}'s graph takes ({Settings.MaxFrameIndex - 1})";
            return null;
        }
    }
}
