namespace DeltaInterpolator.Core.Blends
{
    /// <summary>What a track plays at one time (<see cref="TrackLayout.Locate"/>).</summary>
    public readonly struct TrackMoment
    {
        internal TrackMoment(TrackMomentKind kind, int clip, double localTime, int span, double fraction, TrackExtrapolation extrapolation = TrackExtrapolation.None)
        {
            Extrapolation = extrapolation;
            Kind = kind;
            Clip = clip;
            LocalTime = localTime;
            Span = span;
            Fraction = fraction;
        }

        /// <summary>Nothing, one clip, or a blend or gap.</summary>
        public TrackMomentKind Kind { get; }

        /// <summary>The clip playing alone (for <see cref="TrackMomentKind.Clip"/>), else −1.</summary>
        public int Clip { get; }

        /// <summary>None inside the clip; before its start or after its end, the extrapolation that plays it there.</summary>
        public TrackExtrapolation Extrapolation { get; }

        /// <summary>Its animation time (extrapolated outside the clip).</summary>
        public double LocalTime { get; }

        /// <summary>The span's index in <see cref="TrackLayout.Spans"/> (for <see cref="TrackMomentKind.Span"/>), else −1.</summary>
        public int Span { get; }

        /// <summary>How far into the span, 0 at its start to 1 at its end.</summary>
        public double Fraction { get; }
    }

    /// <summary>What kind of moment a <see cref="TrackMoment"/> is.</summary>
    public enum TrackMomentKind
    {
        /// <summary>Before the first clip or after the last where that clip has no extrapolation: the track plays nothing (as an Animation Track).</summary>
        None,

        /// <summary>One clip plays alone, as on an Animation Track: inside it, or before the first clip or after the last by its extrapolation.</summary>
        Clip,

        /// <summary>Inside a blend or gap.</summary>
        Span,
    }
}
