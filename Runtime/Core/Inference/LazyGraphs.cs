namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Whether <see cref="InbetweenerLoader"/> loads a model's keys and frame graphs (lazy decoding, one frame at a time).</summary>
    public enum LazyGraphs
    {
        /// <summary>Load them when both are there, otherwise the whole graph alone.</summary>
        IfPresent,

        /// <summary>Refuse a model without them (playback that decodes frame by frame).</summary>
        Required,

        /// <summary>The whole graph only (a bake decodes every gap at once).</summary>
        None,
    }
}
