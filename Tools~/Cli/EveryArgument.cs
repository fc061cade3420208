using DeltaInterpolator.Core.Baking;

namespace DeltaInterpolator.Cli
{
    /// <summary><c>--every</c> of <c>bake</c> and <c>score</c>: a <see cref="KeySpacing"/> in input frames (bare), model frames (<c>mf</c>) or seconds (<c>s</c>).</summary>
    internal static class EveryArgument
    {
        /// <summary>The spacing <paramref name="text"/> names, or null when the option was not given.</summary>
        /// <exception cref="CliErrors.UsageException">Anything else (one line; exit 2).</exception>
        public static KeySpacing? Parse(string? text, string verb)
        {
            if (text == null) return null;
            return KeySpacing.Parse(text) ?? throw new CliErrors.UsageException(
                $"inbetween {verb}: --every '{TerminalText.Safe(text, 40)}'; expected {KeySpacing.Syntax}");
        }
    }
}
