using System;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// A workflow request that cannot be carried out on this motion (a first frame past the clip's end, a
    /// reference frame that is not one of its frames): the message names the source, the problem and what was
    /// expected, for a front end to show as it is.
    /// </summary>
    public sealed class MotionRequestException : ArgumentException
    {
        /// <summary>Creates the exception.</summary>
        public MotionRequestException(string source, string problem, string expected)
            : base(source + ": " + problem + "; " + expected)
        {
        }
    }
}
