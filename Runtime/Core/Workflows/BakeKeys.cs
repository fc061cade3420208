using System;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>Key layouts of a rig's clip that work once it is on the model's timeline.</summary>
    public static class BakeKeys
    {
        /// <summary>
        /// A key every <paramref name="interval"/> rig frames from <paramref name="first"/> and the clip's last
        /// frame, never two keys within one model frame (<see cref="KeyFrames.Every(int, int, int, int)"/>).
        /// </summary>
        /// <exception cref="KeyLayoutException">Interval below 1 or too few frames.</exception>
        public static int[] Every(int interval, MotionClip clip, int first, ModelContract contract)
        {
            if (interval < 1) throw new KeyLayoutException($"a key every {interval} frames", "expected an interval of at least 1 frame");
            return Every(new KeySpacing(interval, KeySpacingUnit.InputFrames), clip, first, contract);
        }

        /// <summary>
        /// Keys <paramref name="spacing"/> apart (input frames, model frames or seconds) from <paramref name="first"/>
        /// by <see cref="KeyPlanner"/>, the last gap kept within the model's trained minimum of missing frames
        /// where the clip allows: the CLI's <c>--every</c> and the editor baker's "every N" share it.
        /// </summary>
        /// <exception cref="KeyLayoutException">A spacing below two model frames or too few frames.</exception>
        public static int[] Every(KeySpacing spacing, MotionClip clip, int first, ModelContract contract)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            return KeyPlanner.Plan(spacing, clip.FrameCount, clip.FrameTime, contract.FramesPerSecond, first, contract.TrainingMissingFrames.Min);
        }
    }
}
