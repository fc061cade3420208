using System;

namespace DeltaInterpolator.Core
{
    /// <summary>
    /// Thrown when an input file (BVH, statistics JSON, model, ...) does not have the expected form.
    /// The message reads <c>SOURCE:LINE: what was wrong; what was expected</c>, so a command-line tool can
    /// print it as one line and an editor can jump to the place; a problem of the file as a whole (no
    /// line to point at) reads <c>SOURCE: what was wrong; what was expected</c> and has <see cref="Line"/> 0.
    /// </summary>
    public class DataFormatException : Exception
    {
        /// <summary>Creates the exception; <see cref="Exception.Message"/> is built from the parts.</summary>
        /// <param name="source">The file path or another name of the input (never null).</param>
        /// <param name="line">1-based line number where the problem was found.</param>
        /// <param name="problem">What was wrong, e.g. <c>"found 'Xrot'"</c>.</param>
        /// <param name="expected">What was expected instead, e.g. <c>"expected a channel name such as Xrotation"</c>.</param>
        public DataFormatException(string source, int line, string problem, string expected)
            : base(source + ":" + line + ": " + problem + "; " + expected)
        {
            Source = source;
            Line = line;
            Problem = problem;
            Expected = expected;
        }

        /// <summary>Creates the exception for a problem of the file as a whole; <see cref="Line"/> is 0.</summary>
        /// <param name="source">The file path or another name of the input (never null).</param>
        /// <param name="problem">What was wrong, e.g. <c>"the skeleton differs from walk1_subject5.bvh's"</c>.</param>
        /// <param name="expected">What was expected instead, starting with "expected".</param>
        public DataFormatException(string source, string problem, string expected)
            : base(source + ": " + problem + "; " + expected)
        {
            Source = source;
            Line = 0;
            Problem = problem;
            Expected = expected;
        }

        /// <summary>The file path or name of the input that was being read.</summary>
        public new string Source { get; }

        /// <summary>1-based line number of the problem; 0 when the problem is the file as a whole.</summary>
        public int Line { get; }

        /// <summary>What was wrong.</summary>
        public string Problem { get; }

        /// <summary>What was expected instead.</summary>
        public string Expected { get; }
    }
}
