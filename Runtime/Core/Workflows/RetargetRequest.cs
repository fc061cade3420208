using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>What <see cref="MotionRetargeting"/> is asked to do with a clip besides mapping it.</summary>
    public sealed class RetargetRequest
    {
        /// <summary>The source clip's frame that is its reference pose, or null for its default pose.</summary>
        public int? ReferenceFrame { get; set; }

        /// <summary>The first source frame used (frames before it — a T-pose, conversion artefacts — are dropped).</summary>
        public int FromFrame { get; set; }

        /// <summary>The source's true frame rate when its header is wrong, or null.</summary>
        public double? InputFps { get; set; }

        /// <summary>The output's frame rate, or null: the model's on the model's skeleton, the source's on another rig.</summary>
        public double? OutputFps { get; set; }

        /// <summary>Model units per source unit, or null to scale the root by leg length.</summary>
        public double? Scale { get; set; }

        /// <summary>A user joint map, or null for the best built-in one.</summary>
        public JointMap? Map { get; set; }

        /// <summary>The up axis of the files' worlds (<see cref="UpAxis.Auto"/>: detected per file; see <see cref="UpAxisDecision"/>).</summary>
        public UpAxis Up { get; set; } = UpAxis.Auto;

        /// <summary>For a target rig: its frame that is its reference pose, or null for its default pose.</summary>
        public int? TargetReferenceFrame { get; set; }

        /// <summary>
        /// Keep reference poses the humanoid rule (<see cref="Retargeting.BoneDirections.UprightBones"/> within 25°) refuses:
        /// the CLI's --accept-reference-pose. What was accepted is in <see cref="RetargetResult.AcceptedReference"/>.
        /// </summary>
        public bool AcceptReferencePose { get; set; }
    }
}
