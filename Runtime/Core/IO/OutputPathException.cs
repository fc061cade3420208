using System;

namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// An output path that cannot or must not be written (exists without <c>--force</c>, is an input, is a
    /// folder, is not writable). The message reads <c>PATH: what was wrong; what was expected</c>.
    /// </summary>
    public sealed class OutputPathException : Exception
    {
        /// <summary>Creates the exception from its parts.</summary>
        public OutputPathException(string path, string problem, string expected)
            : base(path + ": " + problem + "; " + expected)
        {
            Path = path;
            Problem = problem;
            Expected = expected;
        }

        /// <summary>What is wrong with the path, e.g. "already exists".</summary>
        public string Problem { get; }

        /// <summary>What was expected instead, starting with "expected".</summary>
        public string Expected { get; }

        /// <summary>The output path as the user gave it.</summary>
        public string Path { get; }
    }
}
