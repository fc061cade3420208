using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>The one rule that chooses how a rig's motion reaches a model: as it is, or through a skeleton map.</summary>
    public static class RigRetargeting
    {
        /// <summary>
        /// <see cref="SameRig"/> when <paramref name="clip"/> is on the model's skeleton at its frame rate and no
        /// reference frame or joint map asks for a map; otherwise a <see cref="MappedRig"/> (any humanoid; joints
        /// the rig lacks are synthesized).
        /// </summary>
        /// <param name="contract">The model's contract (skeleton, frame rate).</param>
        /// <param name="clip">The rig's motion.</param>
        /// <param name="source">Where it came from, for messages.</param>
        /// <param name="referenceFrame">The clip frame that is the rig's reference pose, or null for its default pose.</param>
        /// <param name="map">A user joint map, or null for the best built-in one.</param>
        /// <param name="up">The file's up axis (auto: detected; a Z-up file on the model's skeleton goes through a map).</param>
        /// <exception cref="JointMapException">The rig cannot be mapped (joints missing).</exception>
        /// <exception cref="MotionRequestException">The reference frame is not a frame of the clip.</exception>
        /// <param name="acceptReferencePose">Keep a reference pose the humanoid rule refuses, reported in <see cref="IRigRetargeting.Description"/> (<see cref="MappedRig.Create"/>).</param>
        public static IRigRetargeting For(ModelContract contract, MotionClip clip, string source, int? referenceFrame = null, JointMap? map = null, UpAxis up = UpAxis.Auto, bool acceptReferencePose = false)
        {
            var report = new ModelCheckReport();
            ModelChecks.Skeleton(contract, clip.Skeleton, source, report);
            if (!report.HasErrors && referenceFrame == null && map == null && SameRig.AtModelRate(contract, clip.FrameTime)
                && UpAxisDecision.Decide(up, ReferencePose.Default(clip.Skeleton), false, clip, JointMap.Lafan1).IsIdentity)
            {
                return new SameRig(contract, clip, source);
            }

            return MappedRig.Create(contract, clip, referenceFrame, source, map, up, acceptReferencePose);
        }
    }
}
