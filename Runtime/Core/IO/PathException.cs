using System;

namespace DeltaInterpolator.Core.IO
{
    /// <summary>
    /// A path given by the user that cannot be used as it stands; the message reads
    /// <c>PATH: what was wrong; what was expected</c> (the one-line refusal every reader of paths gives).
    /// </summary>
    public abstract class PathException : Exception
    {
        /// <summary>Creates the exception from its parts.</summary>
        protected PathException(string path, string problem, string expected)
            : base(path + ": " + problem + "; " + expected)
        {
            Path = path;
            Problem = problem;
            Expected = expected;
        }

        /// <summary>What was wrong with the path, e.g. <c>"is a directory"</c> or <c>"already exists"</c>.</summary>
        public string Problem { get; }

        /// <summary>What was expected instead, starting with "expected".</summary>
        public string Expected { get; }

        /// <summary>The path as the user gave it.</summary>
        public string Path { get; }
    }
}
