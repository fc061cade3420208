using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>What one <c>bake</c> of both methods produced, on the model's skeleton and on the input's (used by <c>bake</c> and <c>demo</c>).</summary>
    internal sealed class BakeOutcome
    {
        public BakeOutcome(IBakeRetargeting seam, MotionClip groundTruthOnModel, int[] modelKeys, BakePlan modelPlan, BakeSettings modelSettings,
            MotionClip modelOnModel, MotionClip slerpOnModel, MotionClip modelOut, MotionClip slerpOut, double modelSeconds, double slerpSeconds)
        {
            Seam = seam;
            GroundTruthOnModel = groundTruthOnModel;
            ModelKeys = modelKeys;
            ModelPlan = modelPlan;
            ModelSettings = modelSettings;
            ModelOnModel = modelOnModel;
            SlerpOnModel = slerpOnModel;
            ModelOut = modelOut;
            SlerpOut = slerpOut;
            ModelSeconds = modelSeconds;
            SlerpSeconds = slerpSeconds;
        }

        /// <summary>How the input reached the model's skeleton and rate.</summary>
        public IBakeRetargeting Seam { get; }

        /// <summary>The input on the model's skeleton and rate (all its frames are the truth there; only the keys were baked from).</summary>
        public MotionClip GroundTruthOnModel { get; }

        /// <summary>The keys as frames of <see cref="GroundTruthOnModel"/>.</summary>
        public int[] ModelKeys { get; }

        /// <summary>The model's plan (gaps, warnings).</summary>
        public BakePlan ModelPlan { get; }

        /// <summary>The model's settings (past frames, policy).</summary>
        public BakeSettings ModelSettings { get; }

        /// <summary>The model's bake on the model's skeleton: frames ModelKeys[0]..ModelKeys[last].</summary>
        public MotionClip ModelOnModel { get; }

        /// <summary>SLERP's bake on the model's skeleton.</summary>
        public MotionClip SlerpOnModel { get; }

        /// <summary>The model's bake on the input's skeleton and rate: input frames keys[0]..keys[last].</summary>
        public MotionClip ModelOut { get; }

        /// <summary>SLERP's bake on the input's skeleton and rate.</summary>
        public MotionClip SlerpOut { get; }

        /// <summary>Seconds the model's bake took.</summary>
        public double ModelSeconds { get; }

        /// <summary>Seconds SLERP's bake took.</summary>
        public double SlerpSeconds { get; }
    }
}
