using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>
    /// What a <see cref="ClipBaker"/> must know about its in-betweener: how many past frames it wants,
    /// what to feed when fewer exist, the longest request its graph can take, and the ranges it was
    /// trained on (gaps outside them are baked with a warning). <see cref="ForModel"/> reads all of it
    /// from a model contract; <see cref="ForBaseline"/> suits SLERP and zero-velocity, which use only the
    /// last past frame and the target.
    /// </summary>
    public sealed class BakeSettings
    {
        /// <summary>Past frames the in-betweener wants before each gap (≥ 1).</summary>
        public int PastFrames { get; set; } = 1;

        /// <summary>What to feed when fewer than <see cref="PastFrames"/> frames exist before a gap.</summary>
        public ShortContextPolicy ShortContext { get; set; } = ShortContextPolicy.FeedAvailable;

        /// <summary>
        /// True (the default): the frames before a gap that earlier gaps filled count as past context, as
        /// key frames do. False: only key frames count — the run of consecutive keys ending at the gap's
        /// first key (usually that key alone, then laid out under <see cref="ShortContext"/>), so the
        /// in-betweener never sees its own output.
        /// </summary>
        public bool FilledFramesAsContext { get; set; } = true;

        /// <summary>
        /// Largest frame index a request may use: past keys P plus missing frames n must satisfy
        /// P + n ≤ this (the target's index). <see cref="int.MaxValue"/> for no limit.
        /// </summary>
        public int MaxFrameIndex { get; set; } = int.MaxValue;

        /// <summary>Past-key counts the model was trained on, or null when any count is fine.</summary>
        public (int Min, int Max)? TrainedPastFrames { get; set; }

        /// <summary>Gap lengths the model was trained on, or null when any length is fine.</summary>
        public (int Min, int Max)? TrainedMissingFrames { get; set; }

        /// <summary>
        /// Foot locking applied to the filled frames once every gap is baked (<see cref="Feet.FootLocker"/>: planted
        /// feet held, key frames untouched), or null (the default) for none. The clip must have the model's leg
        /// joints (LaFAN1 names).
        /// </summary>
        public Feet.FootLockSettings? FootLocking { get; set; }

        /// <summary>A copy with <see cref="FootLocking"/> replaced (the bake workflow locks a retargeted rig's feet on the rig itself).</summary>
        internal BakeSettings WithFootLocking(Feet.FootLockSettings? footLocking)
        {
            var copy = (BakeSettings)MemberwiseClone();
            copy.FootLocking = footLocking;
            return copy;
        }

        /// <summary>Name used in warnings and refusals, e.g. the model file.</summary>
        public string Name { get; set; } = "the in-betweener";

        /// <summary>Settings for an in-betweener that needs only the last past frame (SLERP, zero-velocity): no limits.</summary>
        public static BakeSettings ForBaseline(string name = "the baseline") => new BakeSettings { Name = name };

        /// <summary>
        /// Settings for a model: it wants the largest past-key count it was trained on (10 when the
        /// contract does not say), the short-context policy of <see cref="ChooseShortContext"/> unless
        /// <paramref name="shortContext"/> overrides it, the graph's largest frame index, and the
        /// contract's training ranges for warnings.
        /// </summary>
        public static BakeSettings ForModel(ModelContract contract, ShortContextPolicy? shortContext = null)
        {
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            (int Min, int Max) past = contract.TrainingPastFrames;
            (int Min, int Max) missing = contract.TrainingMissingFrames;
            bool pastKnown = past.Max >= 1;
            return new BakeSettings
            {
                PastFrames = pastKnown ? past.Max : DefaultModelPastFrames,
                ShortContext = shortContext ?? ChooseShortContext(contract.TrainingPastFrames),
                MaxFrameIndex = contract.MaxFrameIndex,
                TrainedPastFrames = pastKnown ? past : ((int, int)?)null,
                TrainedMissingFrames = missing.Max >= 1 ? missing : ((int, int)?)null,
                Name = contract.Source,
            };
        }

        /// <summary>
        /// The short-context policy for a model trained on <paramref name="trainedPastFrames"/> past keys:
        /// <see cref="ShortContextPolicy.FeedAvailable"/> when the range starts at one frame (the model
        /// has seen every count a clip can offer), otherwise <see cref="ShortContextPolicy.RepeatEarliest"/>
        /// (measured for the shipped model, trained at 10 only: see <see cref="ShortContextPolicy"/>).
        /// An unknown range (0, 0) counts as a fixed 10.
        /// </summary>
        public static ShortContextPolicy ChooseShortContext((int Min, int Max) trainedPastFrames)
        {
            return trainedPastFrames.Max >= 1 && trainedPastFrames.Min <= 1 ? ShortContextPolicy.FeedAvailable : ShortContextPolicy.RepeatEarliest;
        }

        /// <summary>Past keys assumed for a model whose contract has no training range: the benchmark's layout.</summary>
        public const int DefaultModelPastFrames = 10;
    }
}
