namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// How a clip plays outside its own time on the track: Timeline's <c>TimelineClip.ClipExtrapolation</c>, the same
    /// five modes in the same meaning (<c>TimelineClip.GetExtrapolatedTime</c>, Timeline 1.8.10 <c>Runtime/TimelineClip.cs:767-810</c>).
    /// </summary>
    public enum TrackExtrapolation
    {
        /// <summary>Nothing plays (the default of a clip on a custom track: Timeline's <c>TimelineClip</c> sets none).</summary>
        None = 0,

        /// <summary>The clip's first (before it) or last (after it) frame is held (the default Timeline's Animation Track gives a new clip).</summary>
        Hold = 1,

        /// <summary>The clip repeats.</summary>
        Loop = 2,

        /// <summary>The clip repeats, reversing at each end.</summary>
        PingPong = 3,

        /// <summary>The clip's time runs on past its ends, as if it were longer.</summary>
        Continue = 4,
    }
}
