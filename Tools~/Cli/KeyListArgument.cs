using System.Text.RegularExpressions;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// A <c>--keys</c> value: the frame indices themselves (<c>0,12,40</c>) or <c>@FILE</c>, a file holding
    /// them separated by commas, spaces or line breaks — for key lists longer than a command line should be
    /// (<see cref="Program.MaxCommandLineCharacters"/>).
    /// </summary>
    internal static class KeyListArgument
    {
        /// <summary>The largest key list file read (about a million keys).</summary>
        public const long MaxFileBytes = 8 << 20;

        /// <summary>The file that <paramref name="value"/> names after '@' (an input of the command), or null for a literal key list.</summary>
        public static string? FilePath(string value)
        {
            return value.StartsWith("@", System.StringComparison.Ordinal) ? value.Substring(1) : null;
        }

        /// <summary>
        /// The comma-separated key list that <paramref name="value"/> means: itself, or the contents of the
        /// file it names after '@' with every run of spaces, commas and line breaks made one comma.
        /// </summary>
        /// <exception cref="InputPathException">The file is missing, not a regular file, or too large.</exception>
        public static string Text(string value)
        {
            string? path = FilePath(value);
            if (path == null) return value;
            string text = InputFile.ReadAllText(path, "a key list file (frame indices separated by commas, spaces or lines)", MaxFileBytes);
            return Regex.Replace(text.Trim(), @"[\s,]+", ",");
        }
    }
}
