using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// A source skeleton cannot be mapped onto a target skeleton: joints the target needs are missing
    /// (<see cref="MissingJoints"/> names them) or the map's chains do not fit the source's hierarchy.
    /// The message reads <c>SOURCE: what was wrong; what was expected</c> (one line; the CLI exits with 2).
    /// </summary>
    public sealed class JointMapException : Exception
    {
        /// <summary>Creates the exception; the message is built from the parts.</summary>
        public JointMapException(string source, string problem, string expected, IReadOnlyList<string>? missingJoints = null)
            : base(source + ": " + problem + "; " + expected)
        {
            Source = source;
            Problem = problem;
            Expected = expected;
            MissingJoints = missingJoints ?? Array.Empty<string>();
        }

        /// <summary>The source skeleton's file or name.</summary>
        public new string Source { get; }

        /// <summary>What was wrong.</summary>
        public string Problem { get; }

        /// <summary>What was expected instead.</summary>
        public string Expected { get; }

        /// <summary>The target joints no source joint was found for (empty when the problem is another).</summary>
        public IReadOnlyList<string> MissingJoints { get; }
    }
}
