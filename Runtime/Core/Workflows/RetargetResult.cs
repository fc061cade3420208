using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>The motion <see cref="MotionRetargeting"/> produced and the maps it went through.</summary>
    public sealed class RetargetResult
    {
        internal RetargetResult(MotionClip motion, SkeletonMap toModel, SkeletonMap? fromModel, string? acceptedReference = null)
        {
            AcceptedReference = acceptedReference;
            Motion = motion;
            ToModel = toModel;
            FromModel = fromModel;
        }

        /// <summary>The retargeted motion (on the model's skeleton, or on the target rig's).</summary>
        public MotionClip Motion { get; }

        /// <summary>The source rig → the model's skeleton.</summary>
        public SkeletonMap ToModel { get; }

        /// <summary>The target rig ↔ the model's skeleton, or null when the target is the model.</summary>
        public SkeletonMap? FromModel { get; }

        /// <summary>
        /// With <see cref="RetargetRequest.AcceptReferencePose"/>: the reference pose(s) the humanoid rule would have
        /// refused (bones and angles), for every output of the run to report; null when nothing was accepted.
        /// </summary>
        public string? AcceptedReference { get; }
    }
}
