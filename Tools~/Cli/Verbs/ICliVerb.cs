using System.CommandLine;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// One verb of the <c>inbetween</c> tool. Implementations build their command (options, help text,
    /// action); the action returns the exit status and throws <see cref="Core.DataFormatException"/> or
    /// <see cref="CliErrors.UsageException"/> for bad input, which <see cref="CliErrors"/> reports.
    /// </summary>
    public interface ICliVerb
    {
        /// <summary>Creates the command with its options and action.</summary>
        Command CreateCommand();
    }
}
