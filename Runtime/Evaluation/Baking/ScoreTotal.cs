namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>
    /// Frame-weighted means of some rows of a <see cref="ScoreSheet"/>, per method, and their ratios to the baseline (the
    /// last method). Built by <see cref="ScoreSheet.Total()"/>.
    /// </summary>
    /// <param name="Files">Files added up.</param>
    /// <param name="Frames">Non-key frames added up.</param>
    /// <param name="Errors">
    /// Every method's errors: position and L2Q weighted by the rows' frames, foot skating by their planted (frame, joint)
    /// pairs (NaN with none).
    /// </param>
    public sealed record ScoreTotal(int Files, int Frames, MethodErrors Errors);
}
