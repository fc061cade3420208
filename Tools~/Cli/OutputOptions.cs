using System.Collections.Generic;
using System.CommandLine;
using DeltaInterpolator.Core.IO;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// The output rule of every verb that writes files, as one option and one check: <c>--force</c>
    /// allows replacing an existing output; <see cref="Check"/> runs <see cref="OutputFile.Check(string, bool, IEnumerable{string})"/>
    /// before any work; the verb then writes with <see cref="OutputFile.Write"/> (temporary file beside
    /// the target, renamed into place when complete). <see cref="HelpText"/> states the rule for the
    /// verb's help.
    /// </summary>
    public sealed class OutputOptions
    {
        /// <summary>The rule, for a verb's description (<c>--help</c>).</summary>
        public const string HelpText =
            "Outputs: an existing file is replaced only with --force; an output that is also an input, a folder, a named pipe or a device\n" +
            "is refused; output paths are checked before any work, and each file is written to a temporary file beside it and renamed\n" +
            "into place when complete, so a failure never leaves half a file or a damaged old one.";

        /// <summary>Declares <c>--force</c>.</summary>
        public OutputOptions()
        {
            Force = new Option<bool>("--force")
            {
                Description = "Replace existing output files (without it, an existing output is refused before any work).",
            };
        }

        /// <summary><c>--force</c>: replace existing outputs.</summary>
        public Option<bool> Force { get; }

        /// <summary>Adds the options to <paramref name="command"/>.</summary>
        public void AddTo(Command command)
        {
            command.Options.Add(Force);
        }

        /// <summary>
        /// Checks one output path before any work (see <see cref="OutputFile.Check(string, bool, IEnumerable{string})"/>);
        /// returns its full path. Throws <see cref="OutputPathException"/>, which the CLI reports as one line with exit 2.
        /// </summary>
        /// <param name="parse">The parsed command line (for <c>--force</c>).</param>
        /// <param name="path">The output path as given.</param>
        /// <param name="inputs">Every file and folder the command reads, and the command's other outputs.</param>
        public string Check(ParseResult parse, string path, IEnumerable<string?> inputs)
        {
            return OutputFile.Check(path, parse.GetValue(Force), inputs);
        }
    }
}
