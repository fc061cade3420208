namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// Thrown by <see cref="BvhReader"/> for every kind of malformed BVH input (empty or truncated file,
    /// missing section, bad number, unknown channel, unbalanced braces, ...). The message reads
    /// <c>FILE:LINE: what was wrong; what was expected</c>.
    /// </summary>
    public sealed class BvhFormatException : DataFormatException
    {
        /// <summary>Creates the exception.</summary>
        public BvhFormatException(string source, int line, string problem, string expected)
            : base(source, line, problem, expected)
        {
        }
    }
}
