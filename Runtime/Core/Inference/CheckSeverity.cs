namespace DeltaInterpolator.Core.Inference
{
    /// <summary>How much a <see cref="ModelCheck"/> matters (the levels of the editor's help boxes).</summary>
    public enum CheckSeverity
    {
        /// <summary>Worth knowing; nothing to fix (e.g. metadata fields this runtime does not read).</summary>
        Info,
        /// <summary>Runs, but the result may be poor (e.g. a gap longer than any seen in training).</summary>
        Warning,
        /// <summary>Cannot run correctly: loading or the request is refused.</summary>
        Error,
    }
}
