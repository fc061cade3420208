namespace DeltaInterpolator.Core.Blends
{
    /// <summary>What fills a blend or gap on a neural track.</summary>
    public enum BlendMode
    {
        /// <summary>The model's in-between.</summary>
        Model,

        /// <summary>SLERP of the two key poses: a gap the model cannot fill (outside its trained range, or under one missing frame).</summary>
        Slerp,

        /// <summary>Timeline's own crossfade of the two clips: a blend the model cannot fill.</summary>
        Crossfade,
    }
}
