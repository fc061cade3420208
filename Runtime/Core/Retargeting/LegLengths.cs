using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// The one measure of a character's size that retargeting, foot locking and the skating measure share.
    /// </summary>
    internal static class LegLengths
    {
        /// <summary>
        /// A skeleton's leg length as retargeting measures it: the height of <paramref name="root"/> above the
        /// lowest of <paramref name="joints"/> in <paramref name="pose"/> (Y up). Foot locking and the foot-skating
        /// measure use the same length, so their thresholds scale with the character as the root does.
        /// </summary>
        public static double Measure(ReferencePose pose, IReadOnlyList<int> joints, int root)
        {
            double lowest = double.PositiveInfinity;
            foreach (int j in joints) lowest = Math.Min(lowest, pose.GlobalPosition(j).Y);
            return pose.GlobalPosition(root).Y - lowest;
        }
    }
}
