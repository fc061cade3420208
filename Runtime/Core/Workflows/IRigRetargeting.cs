using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// The seam between a rig's motion and the model's skeleton and frame rate, before and after a bake:
    /// <see cref="ToModel"/> turns the rig's clip into motion on the model's skeleton at the model's rate
    /// (keys mapped onto it), <see cref="FromModel"/> turns baked motion back onto the rig's skeleton and
    /// rate. <see cref="SameRig"/> when the rig is the model's, <see cref="MappedRig"/> for any other
    /// humanoid; <see cref="RigRetargeting.For"/> chooses. The CLI, the editor baker and scoring share it.
    /// </summary>
    public interface IRigRetargeting
    {
        /// <summary>One line for a summary, e.g. "input on the model's skeleton at its frame rate (no retargeting)".</summary>
        string Description { get; }

        /// <summary>The skeleton map for a retargeted rig; null when the rig is the model's.</summary>
        SkeletonMap? Map { get; }

        /// <summary>The rig's leg length in its own units (root height above its lowest mapped joint in the reference pose): what scores are divided by.</summary>
        double LegLength { get; }

        /// <summary>The largest angle (degrees) between a mapped-back key rotation and the rig's own, before the rig's were copied in (0 for the model's rig).</summary>
        double KeyRoundTripDegrees { get; }

        /// <summary>Rig frame indices of keys → frame indices of <see cref="ToModel"/>'s clip.</summary>
        /// <exception cref="Baking.KeyLayoutException">Keys out of range, not increasing, or two on one model frame.</exception>
        int[] KeysToModel(int[] rigKeys);

        /// <summary>The rig's clip on the model's skeleton at the model's frame rate (up to the last key), <see cref="KeysToModel"/>'s frames holding the key poses.</summary>
        /// <exception cref="Baking.KeyLayoutException">Keys out of range, not increasing, or two on one model frame.</exception>
        MotionClip ToModel(MotionClip rigClip, int[] rigKeys);

        /// <summary>
        /// A baked clip (model skeleton and rate, frames of the first to the last model key) → the rig's skeleton and
        /// rate, spanning rig frames rigKeys[0]..rigKeys[last], key frames equal to the rig's.
        /// </summary>
        MotionClip FromModel(MotionClip baked, MotionClip rigClip, int[] rigKeys);
    }
}
