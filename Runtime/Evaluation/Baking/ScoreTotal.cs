namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>Frame-weighted means of some rows of a <see cref="ScoreSheet"/>, per method, and their ratios to the baseline (the last method).</summary>
    public sealed class ScoreTotal
    {
        internal ScoreTotal(int files, int frames, MethodErrors errors)
        {
            Files = files;
            Frames = frames;
            Errors = errors;
        }

        /// <summary>Files added up.</summary>
        public int Files { get; }

        /// <summary>Non-key frames added up.</summary>
        public int Frames { get; }

        /// <summary>
        /// Every method's errors: position and L2Q weighted by the rows' frames, foot skating by their planted (frame, joint)
        /// pairs (NaN with none).
        /// </summary>
        public MethodErrors Errors { get; }
    }
}
