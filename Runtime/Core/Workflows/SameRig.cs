using System;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>The identity seam: the rig is the model's skeleton (same joints, same parents) at the model's frame rate.</summary>
    public sealed class SameRig : IRigRetargeting
    {
        private readonly string _source;

        internal SameRig(ModelContract contract, MotionClip clip, string source)
        {
            _source = source;
            // The leg length as SkeletonMap defines it, so that scores of both seams compare.
            LegLength = SkeletonMap.Create(ReferencePose.Default(clip.Skeleton), ReferencePose.ModelTPose(contract.Skeleton), null, source).SourceLegLength;
        }

        /// <inheritdoc />
        public string Description => "input on the model's skeleton at its frame rate (no retargeting)";

        /// <inheritdoc />
        public SkeletonMap? Map => null;

        /// <inheritdoc />
        public double LegLength { get; }

        /// <inheritdoc />
        public double KeyRoundTripDegrees => 0;

        /// <inheritdoc />
        public int[] KeysToModel(int[] rigKeys) => rigKeys;

        /// <inheritdoc />
        public MotionClip ToModel(MotionClip rigClip, int[] rigKeys) => rigClip;

        /// <inheritdoc />
        public MotionClip FromModel(MotionClip baked, MotionClip rigClip, int[] rigKeys) => baked;

        /// <summary>True when <paramref name="frameTime"/> is the model's rate: BVH files round their frame time (LaFAN1: 0.033333), so within 0.01 %.</summary>
        internal static bool AtModelRate(ModelContract contract, double frameTime)
        {
            double modelFrameTime = 1.0 / contract.FramesPerSecond;
            return Math.Abs(frameTime - modelFrameTime) <= 1e-4 * modelFrameTime;
        }
    }
}
