using System;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// Where one clip sits on a track, as Timeline places it: its start and duration on the track, where in its
    /// animation it starts (clip-in) and that animation's length, all in seconds.
    /// </summary>
    public readonly struct TrackClipTiming
    {
        /// <summary>A clip placement; every value is checked (<see cref="ArgumentOutOfRangeException"/> names the parameter).</summary>
        /// <param name="start">Track time of the clip's first frame (≥ 0).</param>
        /// <param name="duration">How long the clip lasts on the track (&gt; 0).</param>
        /// <param name="clipIn">Time in the animation at the clip's start (≥ 0).</param>
        /// <param name="animationLength">The animation's own length (&gt; 0).</param>
        public TrackClipTiming(double start, double duration, double clipIn, double animationLength)
        {
            if (!(start >= 0) || double.IsInfinity(start)) throw new ArgumentOutOfRangeException(nameof(start), start, "expected a clip start of at least 0 seconds");
            if (!(duration > 0) || double.IsInfinity(duration)) throw new ArgumentOutOfRangeException(nameof(duration), duration, "expected a clip duration above 0 seconds");
            if (!(clipIn >= 0) || double.IsInfinity(clipIn)) throw new ArgumentOutOfRangeException(nameof(clipIn), clipIn, "expected a clip-in of at least 0 seconds");
            if (!(animationLength > 0) || double.IsInfinity(animationLength)) throw new ArgumentOutOfRangeException(nameof(animationLength), animationLength, "expected an animation length above 0 seconds");
            Start = start;
            Duration = duration;
            ClipIn = clipIn;
            AnimationLength = animationLength;
        }

        /// <summary>Track time of the clip's first frame.</summary>
        public double Start { get; }

        /// <summary>How long the clip lasts on the track.</summary>
        public double Duration { get; }

        /// <summary>Track time of the clip's end.</summary>
        public double End => Start + Duration;

        /// <summary>Time in the animation at <see cref="Start"/>.</summary>
        public double ClipIn { get; }

        /// <summary>The animation's own length.</summary>
        public double AnimationLength { get; }

        /// <summary>
        /// The animation's time at track time <paramref name="trackTime"/>, held at its first and last frame: a blend's keys
        /// never wrap a loop, so what the model starts from is the pose the clip shows there when it does not loop.
        /// </summary>
        public double LocalTime(double trackTime) => Math.Max(0, Math.Min(AnimationLength, ClipIn + trackTime - Start));
    }
}
