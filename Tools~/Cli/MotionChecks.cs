using System;
using System.Globalization;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// Checks on motion before a verb writes or draws it: joint positions (forward kinematics) must be finite
    /// numbers. Values near 1e308 are finite in a file yet overflow once offsets are added or errors are
    /// squared, which gave NaN scores, NaN frames and crashed previews.
    /// </summary>
    internal static class MotionChecks
    {
        /// <summary>
        /// Refuses, with <see cref="DataFormatException"/> naming <paramref name="source"/> and the first bad
        /// frame, a clip whose global joint positions are not all finite.
        /// </summary>
        public static void RequireFinitePositions(MotionClip clip, string source, string what)
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
