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
            // Rig frames per model frame (CMU at 120 fps: 4; BVH files round their frame time, so 4.0002 means 4),
            // and one more where it is above 1, so that rounding to model frames can never put two keys on one frame.
            double ratio = 1.0 / (contract.FramesPerSecond * clip.FrameTime);
            int spacing = ratio <= 1 + 1e-3 ? 1 : (int)Math.Ceiling(ratio - 1e-3) + 1;
            return KeyFrames.Every(interval, clip.FrameCount, first, spacing);
        }
    }
}
