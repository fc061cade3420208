namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// An output path that cannot or must not be written (exists without <c>--force</c>, is an input, is a
    /// folder, is not writable). The message reads <c>PATH: what was wrong; what was expected</c>.
    /// </summary>
    public sealed class OutputPathException : PathException
    {
        /// <summary>Creates the exception from its parts.</summary>
        public OutputPathException(string path, string problem, string expected)
            : base(path, problem, expected)
        {
        }
    }
}
