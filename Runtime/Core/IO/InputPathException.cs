namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// An input path that cannot be read as a file: missing, a directory, a named pipe, a device or a
    /// socket. The message reads <c>PATH: what was wrong; what was expected</c>.
    /// </summary>
    public sealed class InputPathException : PathException
    {
        /// <summary>Creates the exception from its parts.</summary>
        public InputPathException(string path, string problem, string expected)
            : base(path, problem, expected)
        {
        }
    }
}
