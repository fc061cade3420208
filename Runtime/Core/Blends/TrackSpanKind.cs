namespace DeltaInterpolator.Core.Blends
{
    /// <summary>What lies between two consecutive clips on a track.</summary>
    public enum TrackSpanKind
    {
        /// <summary>The clips overlap: Timeline would crossfade; the model goes from the first clip's pose where the overlap starts to the second's where it ends.</summary>
        Blend,

        /// <summary>Time between the clips: the model goes from the first clip's last frame to the second's first.</summary>
        Gap,
    }
}
