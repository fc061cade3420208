using System;
using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Evaluation.Benchmark;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// The window layout of <c>inbetween benchmark</c> from its option values (<c>--window</c>, <c>--offset</c>,
    /// <c>--lengths</c>, <c>--past-frames</c>, <c>--past-policy</c>) as validated <see cref="BenchmarkOptions"/>;
    /// every bad value is a usage error that names the option.
    /// </summary>
    internal static class BenchmarkLayoutArguments
    {
        /// <exception cref="CliErrors.UsageException">A value is malformed or out of range.</exception>
        public static BenchmarkOptions Parse(int window, int offset, string lengths, int pastFrames, string pastPolicy)
        {
            var options = new BenchmarkOptions
            {
                Window = window,
                Offset = offset,
                Lengths = ParseLengths(lengths),
                FedPastFrames = pastFrames,
                ShortContext = ParsePolicy(pastPolicy),
            };
            // Checked here, not by Validate: there 0 means "all", which the option does not offer.
            if (options.FedPastFrames < 1 || options.FedPastFrames > options.PastFrames)
            {
                throw new CliErrors.UsageException($"inbetween benchmark: --past-frames {options.FedPastFrames}; expected 1..{options.PastFrames} (the last P of the {options.PastFrames} context frames)");
            }

            try
            {
                options.Validate();
            }
            catch (ArgumentException e)
            {
                throw new CliErrors.UsageException("inbetween benchmark: " + e.Message);
            }

            return options;
        }

        private static ShortContextPolicy ParsePolicy(string text)
        {
            switch (text)
            {
                case "feed": return ShortContextPolicy.FeedAvailable;
                case "repeat": return ShortContextPolicy.RepeatEarliest;
                default: throw new CliErrors.UsageException($"inbetween benchmark: --past-policy '{text}'; expected feed or repeat");
            }
        }

        private static IReadOnlyList<int> ParseLengths(string text)
        {
            var lengths = new List<int>();
            foreach (string part in text.Split(','))
            {
                if (!int.TryParse(part.Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out int n) || n < 1)
                {
                    throw new CliErrors.UsageException($"inbetween benchmark: --lengths '{text}' has '{part.Trim()}'; expected comma-separated whole numbers ≥ 1 such as 5,15,30,45");
                }

                lengths.Add(n);
            }

            return lengths;
        }
    }
}
