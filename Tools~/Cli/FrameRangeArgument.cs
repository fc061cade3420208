using System.Globalization;

namespace DeltaInterpolator.Cli
{
    /// <summary>A <c>--frames START-END</c> value: frame indices of the files, inclusive.</summary>
    internal static class FrameRangeArgument
    {
        /// <summary>The range, or null when the option was not given.</summary>
        /// <exception cref="CliErrors.UsageException">Not two whole numbers with START ≤ END.</exception>
        public static (int Start, int End)? Parse(string? text)
        {
            if (text == null) return null;
            string[] parts = text.Split('-');
            if (parts.Length != 2
                || !int.TryParse(parts[0].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out int start)
                || !int.TryParse(parts[1].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out int end)
                || end < start)
            {
                throw new CliErrors.UsageException($"--frames {text}: not a frame range; expected START-END with 0 ≤ START ≤ END, e.g. 0-299");
            }

            return (start, end);
        }
    }
}
