using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// Checks on motion before a verb writes or draws it. The check itself is Core's
    /// <see cref="FinitePositions"/>, so that the preview assembly (and any front end) applies the same one.
    /// </summary>
    internal static class MotionChecks
    {
        /// <inheritdoc cref="FinitePositions.Require"/>
        public static void RequireFinitePositions(MotionClip clip, string source, string what) => FinitePositions.Require(clip, source, what);

        /// <summary>
        /// Refuses a frame option (<c>--reference-frame</c>, <c>--from-frame</c>) outside the clip, naming the option as
        /// the user typed it; a frame of the clip and null pass. <paramref name="spare"/> frames must follow it.
        /// </summary>
        public static void RequireFrame(MotionClip clip, int? frame, string option, string path, int spare = 0)
        {
            if (frame == null) return;
            int last = clip.FrameCount - 1 - spare;
            if (frame.Value >= 0 && frame.Value <= last) return;
            throw new CliErrors.UsageException(spare == 0
                ? $"{path}: {option} {frame.Value} is not a frame of the file; expected 0 to {last}"
                : $"{path}: {option} {frame.Value} leaves fewer than {spare + 1} of the file's {clip.FrameCount} frames; expected 0 to {System.Math.Max(0, last)}");
        }
    }
}
