using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Evaluation.Benchmark;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Presenters
{
    /// <summary>The lines under the benchmark's tables: what was scored, which statistics, the past-frame layout, and how fast.</summary>
    internal static class BenchmarkSummary
    {
        /// <param name="outcome">The run.</param>
        /// <param name="options">The window layout it ran with.</param>
        /// <param name="statsPath">The <c>--stats</c> file, or null when statistics were computed.</param>
        /// <param name="saveStats">The <c>--save-stats</c> file, or null.</param>
        /// <param name="totalSeconds">Wall time of the whole command so far.</param>
        public static void Print(BenchmarkOutcome outcome, BenchmarkOptions options, string? statsPath, string? saveStats, double totalSeconds)
        {
            string statsLine = statsPath != null
                ? $"statistics: {statsPath}"
                : $"statistics: computed from {outcome.TrainingFileCount} training files in {outcome.StatisticsSeconds:0.00} s{(saveStats != null ? ", saved to " + saveStats : "")}";
            AnsiConsole.MarkupLine(Markup.Escape(
                $"{outcome.Report.WindowCount} windows of {options.Window} frames every {options.Offset} from {outcome.TestFileCount} test files ({outcome.TestFrames:N0} frames); {statsLine}"));
            if (options.EffectivePastFrames != options.PastFrames)
            {
                string layout = options.ShortContext == ShortContextPolicy.RepeatEarliest
                    ? $"repeated to {options.TransitionPastFrames} past keys (--past-policy repeat)"
                    : $"fed alone as {options.TransitionPastFrames} past keys (--past-policy feed)";
                AnsiConsole.MarkupLine(Markup.Escape($"past frames: the last {options.EffectivePastFrames} of {options.PastFrames}, {layout}"));
            }

            double readSeconds = outcome.ReadSeconds;
            long testBytes = outcome.TestBytes;
            AnsiConsole.MarkupLine(Markup.Escape(
                $"read {testBytes / 1e6:0.0} MB in {readSeconds:0.000} s ({testBytes / 1e6 / Math.Max(readSeconds, 1e-9):0} MB/s), evaluated in {outcome.EvaluationSeconds:0.000} s, total {totalSeconds:0.00} s"));
        }
    }
}
