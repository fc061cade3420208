using System;

namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// An input path that cannot be read as a file: missing, a directory, a named pipe, a device or a
    /// socket. The message reads <c>PATH: what was wrong; what was expected</c>.
    /// </summary>
    public sealed class InputPathException : Exception
    {
        /// <summary>Creates the exception from its parts.</summary>
        public InputPathException(string path, string problem, string expected)
            : base(path + ": " + problem + "; " + expected)
        {
            Path = path;
            Problem = problem;
        }

        /// <summary>What was wrong, e.g. <c>"is a directory"</c>.</summary>
        public string Problem { get; }

        /// <summary>The input path as the user gave it.</summary>
        public string Path { get; }
    }
}
