using System;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// Where one clip sits on a track, as Timeline places it: its start and duration on the track, where in its
    /// animation it starts (clip-in) and that animation's length, all in seconds; how fast it plays (Timeline's clip
    /// speed) and whether its animation loops (then the animation time wraps, as Timeline's clip playable wraps it); and how
    /// it plays before and after its own time (Timeline's pre- and post-extrapolation).
    /// </summary>
    public readonly struct TrackClipTiming
    {
        /// <summary>A clip placement; every value is checked (<see cref="ArgumentOutOfRangeException"/> names the parameter).</summary>
        /// <param name="start">Track time of the clip's first frame (≥ 0).</param>
        /// <param name="duration">How long the clip lasts on the track (&gt; 0).</param>
        /// <param name="clipIn">Time in the animation at the clip's start (≥ 0).</param>
        /// <param name="animationLength">The animation's own length (&gt; 0).</param>
        /// <param name="speed">Animation seconds per track second (Timeline's clip speed, <c>TimelineClip.timeScale</c>; &gt; 0).</param>
        /// <param name="loops">Whether the animation wraps at its end (a looping clip) rather than holding its last frame.</param>
        /// <param name="preExtrapolation">How the clip plays before its start (<c>TimelineClip.preExtrapolationMode</c>).</param>
        /// <param name="postExtrapolation">How the clip plays after its end (<c>TimelineClip.postExtrapolationMode</c>).</param>
        public TrackClipTiming(double start, double duration, double clipIn, double animationLength, double speed = 1, bool loops = false,
            TrackExtrapolation preExtrapolation = TrackExtrapolation.None, TrackExtrapolation postExtrapolation = TrackExtrapolation.None)
        {
            if (!(start >= 0) || double.IsInfinity(start)) throw new ArgumentOutOfRangeException(nameof(start), start, "expected a clip start of at least 0 seconds");
            if (!(duration > 0) || double.IsInfinity(duration)) throw new ArgumentOutOfRangeException(nameof(duration), duration, "expected a clip duration above 0 seconds");
            if (!(clipIn >= 0) || double.IsInfinity(clipIn)) throw new ArgumentOutOfRangeException(nameof(clipIn), clipIn, "expected a clip-in of at least 0 seconds");
            if (!(animationLength > 0) || double.IsInfinity(animationLength)) throw new ArgumentOutOfRangeException(nameof(animationLength), animationLength, "expected an animation length above 0 seconds");
            if (!(speed > 0) || double.IsInfinity(speed)) throw new ArgumentOutOfRangeException(nameof(speed), speed, "expected a clip speed above 0 (1: as authored)");
            if (preExtrapolation < TrackExtrapolation.None || preExtrapolation > TrackExtrapolation.Continue)
            {
                throw new ArgumentOutOfRangeException(nameof(preExtrapolation), preExtrapolation, "expected None, Hold, Loop, PingPong or Continue, as Timeline's clip extrapolation");
            }

            if (postExtrapolation < TrackExtrapolation.None || postExtrapolation > TrackExtrapolation.Continue)
            {
                throw new ArgumentOutOfRangeException(nameof(postExtrapolation), postExtrapolation, "expected None, Hold, Loop, PingPong or Continue, as Timeline's clip extrapolation");
            }

            PreExtrapolation = preExtrapolation;
            PostExtrapolation = postExtrapolation;
            Start = start;
            Duration = duration;
            ClipIn = clipIn;
            AnimationLength = animationLength;
            Speed = speed;
            Loops = loops;
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

        /// <summary>Animation seconds per track second.</summary>
        public double Speed { get; }

        /// <summary>Whether the animation wraps at its end.</summary>
        public bool Loops { get; }

        /// <summary>How the clip plays before its start.</summary>
        public TrackExtrapolation PreExtrapolation { get; }

        /// <summary>How the clip plays after its end.</summary>
        public TrackExtrapolation PostExtrapolation { get; }

        /// <summary>
        /// The animation's time at track time <paramref name="trackTime"/> outside the clip, played by
        /// <paramref name="mode"/> as Timeline plays it: the time since the clip's start extrapolated over the clip's
        /// duration (<c>TimelineClip.ToLocalTime</c> → <c>GetExtrapolatedTime</c>, Timeline 1.8.10
        /// <c>Runtime/TimelineClip.cs:608-626, 767-810</c>), then at the clip's speed from its clip-in, wrapped into the
        /// animation when it loops (before its first frame too) and held at its ends otherwise, as the clip's playable plays it.
        /// </summary>
        public double ExtrapolatedTime(double trackTime, TrackExtrapolation mode)
        {
            double unwrapped = PlayedTime(trackTime, mode);
            if (!Loops) return Math.Max(0, Math.Min(AnimationLength, unwrapped));
            double wrapped = unwrapped % AnimationLength;
            return wrapped < 0 ? wrapped + AnimationLength : wrapped;
        }

        /// <summary>
        /// The time the clip's playable is given at track time <paramref name="trackTime"/> when it plays by
        /// <paramref name="mode"/> there (<see cref="TrackExtrapolation.None"/> inside the clip): the time since the clip's start,
        /// extrapolated over its duration as <see cref="ExtrapolatedTime"/> does, at the clip's speed from its clip-in — not
        /// wrapped into the animation nor held at its ends, so that a looping clip's root motion can count its cycles.
        /// </summary>
        public double PlayedTime(double trackTime, TrackExtrapolation mode)
        {
            double time = trackTime - Start, duration = Duration;
            switch (mode)
            {
                case TrackExtrapolation.Loop:
                    if (time < 0) time = duration - (-time % duration);
                    else if (time > duration) time %= duration;
                    break;
                case TrackExtrapolation.Hold:
                    if (time < 0) time = 0;
                    else if (time > duration) time = duration;
                    break;
                case TrackExtrapolation.PingPong:
                    time = time < 0 ? duration * 2 - (-time % (duration * 2)) : time % (duration * 2);
                    time = duration - Math.Abs(time - duration);
                    break;
            }

            return ClipIn + time * Speed;
        }

        /// <summary>
        /// The animation's time at track time <paramref name="trackTime"/> as Timeline plays the clip there: clip-in plus
        /// the track time since the start times the speed, wrapped into the animation when it loops, else held at its
        /// last frame; held at 0 before the animation's first frame (a blend's history never reaches before it).
        /// </summary>
        public double LocalTime(double trackTime)
        {
            double unwrapped = Unwrapped(trackTime);
            if (!(unwrapped > 0)) return 0;
            if (!Loops) return Math.Min(AnimationLength, unwrapped);
            double wrapped = unwrapped % AnimationLength;
            return wrapped < 0 ? 0 : wrapped;
        }

        /// <summary>Animation seconds played from the animation's first frame to track time <paramref name="trackTime"/>, not wrapped or held (negative before it).</summary>
        public double Unwrapped(double trackTime) => ClipIn + (trackTime - Start) * Speed;
    }
}
