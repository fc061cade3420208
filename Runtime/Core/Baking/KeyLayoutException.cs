using System;

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>
    /// Keys that cannot be baked: fewer than two, out of the clip's range, not increasing, duplicated,
    /// or a gap longer than the model's graph can take. The message reads <c>what was wrong; what was
    /// expected</c>, so a tool can print it after the input's name as one line.
    /// </summary>
    public sealed class KeyLayoutException : ArgumentException
    {
        /// <summary>Creates the exception from its two halves.</summary>
        /// <param name="problem">What was wrong, e.g. <c>"key 12 comes after key 40"</c>.</param>
        /// <param name="expected">What was expected instead, e.g. <c>"expected increasing frame indices"</c>.</param>
        public KeyLayoutException(string problem, string expected)
            : base(problem + "; " + expected)
        {
            Problem = problem;
            Expected = expected;
        }

        /// <summary>What was wrong.</summary>
        public string Problem { get; }

        /// <summary>What was expected instead.</summary>
        public string Expected { get; }
    }
}
