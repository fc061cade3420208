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
    }
}
