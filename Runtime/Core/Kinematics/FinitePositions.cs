using System;
using System.Globalization;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Kinematics
{
    /// <summary>
    /// The check on motion before it is written or drawn: joint positions (forward kinematics) must be finite
    /// numbers. Values near 1e308 are finite in a file yet overflow once offsets are added or errors are
    /// squared, which gave NaN scores, NaN frames and crashed previews.
    /// </summary>
    public static class FinitePositions
    {
        /// <summary>
        /// Refuses, with <see cref="DataFormatException"/> naming <paramref name="source"/> and the first bad
        /// frame, a clip whose global joint positions are not all finite (or beyond ±1e150).
        /// </summary>
        /// <param name="clip">The motion.</param>
        /// <param name="source">The file it came from or goes to, for the message.</param>
        /// <param name="what">What the motion is, e.g. "the input" or "the model's result".</param>
        public static void Require(MotionClip clip, string source, string what)
        {
            int j = clip.Skeleton.JointCount;
            var positions = new double[j * 3];
            var rotations = new double[j * 4];
            for (int f = 0; f < clip.FrameCount; f++)
            {
                ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, 1,
                    clip.LocalPositions.AsSpan(clip.PositionIndex(f, 0), j * 3), clip.LocalRotations.AsSpan(clip.RotationIndex(f, 0), j * 4), positions, rotations);
                for (int i = 0; i < positions.Length; i++)
                {
                    double v = positions[i];
                    if (double.IsNaN(v) || double.IsInfinity(v) || Math.Abs(v) > 1e150)
                    {
                        throw new DataFormatException(source,
                            string.Format(CultureInfo.InvariantCulture, "{0}: frame {1}, joint '{2}' is at a position that is not a finite number (or beyond ±1e150)", what, f, clip.Skeleton.Names[i / 3]),
                            "expected motion values of a sensible size (a value like 1e308 overflows); nothing was written");
                    }
                }
            }
        }
    }
}
