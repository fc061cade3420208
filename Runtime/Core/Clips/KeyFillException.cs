using System;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// A fill that cannot be done, refused before any work: an empty clip, no gap, a range outside the clip or
    /// holding fewer than two keys, curves the rig cannot map. <see cref="ArgumentException.ParamName"/> is the
    /// argument at fault (<c>curves</c>, <c>range</c>); the message is one line, <c>CLIP: what; expected …</c>,
    /// the refusal contract's form.
    /// </summary>
    public sealed class KeyFillException : ArgumentException
    {
        /// <summary>Creates the refusal of <paramref name="clip"/>'s <paramref name="paramName"/>.</summary>
        public KeyFillException(string clip, string problem, string expected, string paramName)
            : base(clip + ": " + problem + "; " + expected, paramName)
        {
            Clip = clip;
            Problem = problem;
            Expected = expected;
        }

        /// <summary>The clip's name.</summary>
        public string Clip { get; }

        /// <summary>What was wrong.</summary>
        public string Problem { get; }

        /// <summary>What was expected instead.</summary>
        public string Expected { get; }

        /// <summary>The one line, without .NET's "(Parameter …)" suffix: <see cref="ArgumentException.ParamName"/> carries it.</summary>
        public override string Message => Clip + ": " + Problem + "; " + Expected;
    }
}
