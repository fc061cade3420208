using System.Globalization;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Evaluation.Baking;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>bake --feet lock|off</c> and the foot-skating scores <c>bake</c> prints and writes: each method's
    /// (and the ground truth's own) skating on the input's skeleton and frame rate, in leg lengths per second.
    /// </summary>
    internal static class BakeFeet
    {
        /// <summary>The option's values: foot locking's default settings, or none.</summary>
        /// <exception cref="CliErrors.UsageException">Neither lock nor off.</exception>
        public static FootLockSettings? Parse(string text) => text switch
        {
            "lock" => new FootLockSettings(),
            "off" => null,
            _ => throw new CliErrors.UsageException($"inbetween bake: --feet '{text}'; expected lock or off"),
        };

        /// <summary>The input's legs and leg length: the map's source side for a retargeted input, the model's rig otherwise.</summary>
        public static FootRig Rig(IBakeRetargeting seam, BvhAnimation animation) =>
            seam is SkeletonRetargeting retargeted ? FootRig.ForSource(retargeted.Map) : FootRig.ForModel(animation.Skeleton);

        /// <summary>Foot skating of both methods' results and of the ground truth over the same non-key frames.</summary>
        public static Scores Measure(BvhAnimation animation, int[] inputKeys, BakeOutcome outcome)
        {
            FootRig rig = Rig(outcome.Seam, animation);
            return new Scores(
                FootSkating.Measure(animation.Motion, outcome.ModelOut, inputKeys, rig),
                FootSkating.Measure(animation.Motion, outcome.SlerpOut, inputKeys, rig),
                FootSkating.OfTruth(animation.Motion, inputKeys, rig));
        }

        /// <summary>A skating value for the table: three decimals, or "-" without planted truth frames.</summary>
        public static string Format(FootSkating s) => double.IsNaN(s.MeanSpeed) ? "-" : s.MeanSpeed.ToString("0.000", CultureInfo.InvariantCulture);

        /// <summary>Foot skating of the model, SLERP and the ground truth (leg lengths per second).</summary>
        internal sealed class Scores
        {
            public Scores(FootSkating model, FootSkating slerp, FootSkating truth)
            {
                Model = model;
                Slerp = slerp;
                Truth = truth;
            }

            public FootSkating Model { get; }

            public FootSkating Slerp { get; }

            public FootSkating Truth { get; }
        }
    }
}
