using System.Globalization;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Evaluation.Baking;

namespace DeltaInterpolator.Cli.Baking
{
    /// <summary><c>bake --feet lock|off</c> and how foot-skating values are shown (leg lengths per second).</summary>
    internal static class BakeFeet
    {
        /// <summary>The option's values: foot locking's default settings, or none.</summary>
        /// <exception cref="CliErrors.UsageException">Neither lock nor off.</exception>
        public static FootLockSettings? Parse(string text) => text switch
        {
            "lock" => new FootLockSettings(),
            "off" => null,
            _ => throw new CliErrors.UsageException($"inbetween bake: --feet '{text}'; expected lock or off"),
        };

        /// <summary>A skating value for the table: three decimals, or "-" without planted truth frames.</summary>
        public static string Format(FootSkating s) => double.IsNaN(s.MeanSpeed) ? "-" : s.MeanSpeed.ToString("0.000", CultureInfo.InvariantCulture);
    }
}
