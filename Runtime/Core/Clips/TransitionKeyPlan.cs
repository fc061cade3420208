using System;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// Where the keys of a transition between two clips come from: P past keys sampled from the first clip
    /// up to the transition point (one per model frame, the last on the point itself), then n missing
    /// frames, then the target key sampled from the second clip. Frame indices count from the first past
    /// key, as in a <see cref="Inbetweening.Transition"/>.
    /// </summary>
    public sealed class TransitionKeyPlan
    {
        private TransitionKeyPlan(int pastFrames, int missingFrames, double[] fromTimes, double toTime, double frameRate)
        {
            PastFrames = pastFrames;
            MissingFrames = missingFrames;
            FromTimes = fromTimes;
            ToTime = toTime;
            FrameRate = frameRate;
        }

        /// <summary>Number of past keys P (fewer than asked when the transition point is near the first clip's start).</summary>
        public int PastFrames { get; }

        /// <summary>Number of missing frames n.</summary>
        public int MissingFrames { get; }

        /// <summary>Time (seconds) in the first clip of each past key 0..P−1, ascending.</summary>
        public double[] FromTimes { get; }

        /// <summary>Time (seconds) in the second clip of the target key.</summary>
        public double ToTime { get; }

        /// <summary>The model's frame rate.</summary>
        public double FrameRate { get; }

        /// <summary>Frame index of the target key, P + n.</summary>
        public int TargetFrame => PastFrames + MissingFrames;

        /// <summary>Frames of the baked clip: P + n + 1.</summary>
        public int FrameCount => PastFrames + MissingFrames + 1;

        /// <summary>
        /// Plans a transition leaving the first clip at <paramref name="fromTime"/> and arriving in the
        /// second at <paramref name="toTime"/> after <paramref name="missingFrames"/> in-between frames.
        /// </summary>
        /// <param name="fromTime">Transition point in the first clip (seconds): the last past key.</param>
        /// <param name="toTime">Target time in the second clip (seconds).</param>
        /// <param name="pastFrames">Past keys wanted (the model's trained maximum, e.g. 10); fewer when the first clip is shorter.</param>
        /// <param name="missingFrames">Missing frames n (≥ 1).</param>
        /// <param name="frameRate">The model's frame rate.</param>
        /// <exception cref="ArgumentOutOfRangeException">A count or time is out of range.</exception>
        public static TransitionKeyPlan Create(double fromTime, double toTime, int pastFrames, int missingFrames, double frameRate)
        {
            if (!(frameRate > 0) || double.IsInfinity(frameRate)) throw new ArgumentOutOfRangeException(nameof(frameRate), "the frame rate must be a positive number of frames per second");
            if (!(fromTime >= 0) || double.IsInfinity(fromTime)) throw new ArgumentOutOfRangeException(nameof(fromTime), "the transition point must be a time ≥ 0 in the first clip");
            if (!(toTime >= 0) || double.IsInfinity(toTime)) throw new ArgumentOutOfRangeException(nameof(toTime), "the target must be a time ≥ 0 in the second clip");
            if (pastFrames < 1) throw new ArgumentOutOfRangeException(nameof(pastFrames), "at least one past key is needed");
            if (missingFrames < 1) throw new ArgumentOutOfRangeException(nameof(missingFrames), "at least one missing frame is needed");

            // Past keys step back one model frame each from the transition point; none before the clip starts.
            int available = (int)Math.Floor(fromTime * frameRate + 1e-9) + 1;
            int p = Math.Min(pastFrames, available);
            var times = new double[p];
            for (int k = 0; k < p; k++)
            {
                times[k] = Math.Max(0, fromTime - (p - 1 - k) / frameRate);
            }

            return new TransitionKeyPlan(p, missingFrames, times, toTime, frameRate);
        }
    }
}
