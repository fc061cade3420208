namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// One blend or gap of a <see cref="TrackLayout"/>: the track times it covers, the clips on either side, and the
    /// animation times the model's keys are taken at (the first clip's at <see cref="Start"/> or its end, the second's
    /// at <see cref="End"/> or its start).
    /// </summary>
    public readonly struct TrackSpan
    {
        internal TrackSpan(TrackSpanKind kind, int from, int to, TrackClipTiming fromClip, TrackClipTiming toClip, double start, double end, string? crossfadeReason)
        {
            Kind = kind;
            From = from;
            To = to;
            Start = start;
            End = end;
            FromClip = fromClip;
            ToClip = toClip;
            FromTime = fromClip.LocalTime(start);
            ToTime = toClip.LocalTime(end);
            CrossfadeReason = crossfadeReason;
            // Timeline fills time between two clips with the first one's post-extrapolation, or, only when that is None,
            // the second one's pre-extrapolation (Timeline 1.8.10 Runtime/Utilities/Extrapolation.cs:28-80).
            Extrapolation = kind != TrackSpanKind.Gap ? TrackExtrapolation.None
                : fromClip.PostExtrapolation != TrackExtrapolation.None ? fromClip.PostExtrapolation : toClip.PreExtrapolation;
            bool fromSide = fromClip.PostExtrapolation != TrackExtrapolation.None;
            ExtrapolationOverridden = Extrapolation == TrackExtrapolation.Loop || Extrapolation == TrackExtrapolation.PingPong || Extrapolation == TrackExtrapolation.Continue
                ? $"clip {(fromSide ? from : to)}'s {(fromSide ? "post" : "pre")}-extrapolation is {Extrapolation}, which an Animation Track would play in the gap, but the model's in-between from clip {from}'s last frame to clip {to}'s first plays there; expected Hold or None beside a gap on a neural track (the same result, without this warning)"
                : null;
        }

        /// <summary>Blend (overlap) or gap.</summary>
        public TrackSpanKind Kind { get; }

        /// <summary>Index (in the track's order) of the clip the span leaves.</summary>
        public int From { get; }

        /// <summary>Index of the clip the span arrives in.</summary>
        public int To { get; }

        /// <summary>Where the clip the span leaves sits on the track (its history is read through it: speed, loop).</summary>
        public TrackClipTiming FromClip { get; }

        /// <summary>Where the clip the span arrives in sits on the track.</summary>
        public TrackClipTiming ToClip { get; }

        /// <summary>Track time where the span starts.</summary>
        public double Start { get; }

        /// <summary>Track time where the span ends.</summary>
        public double End { get; }

        /// <summary>Length in seconds.</summary>
        public double Duration => End - Start;

        /// <summary>The first clip's animation time of the span's first pose (the last past key).</summary>
        public double FromTime { get; }

        /// <summary>The second clip's animation time of the span's last pose (the target key).</summary>
        public double ToTime { get; }

        /// <summary>
        /// Why this blend cannot be the model's whatever the model (a clip inside another, a third clip overlapping), so
        /// Timeline's crossfade plays; null for a span the model fills.
        /// </summary>
        public string? CrossfadeReason { get; }

        /// <summary>
        /// What an Animation Track would play in this gap: the first clip's post-extrapolation, or, when that is None, the
        /// second clip's pre-extrapolation (None for a blend). The neural track plays its in-between there whatever it is.
        /// </summary>
        public TrackExtrapolation Extrapolation { get; }

        /// <summary>
        /// Why the gap's in-between overrides what the user set (a Loop, PingPong or Continue that would fill the gap on an
        /// Animation Track), to be said once; null when the gap's extrapolation is Hold or None (the defaults, which mean the
        /// same as the in-between: nothing of its own plays there).
        /// </summary>
        public string? ExtrapolationOverridden { get; }
    }
}
