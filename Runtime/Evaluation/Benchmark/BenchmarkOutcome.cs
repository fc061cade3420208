using System.Globalization;
using DeltaInterpolator.Core;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>
    /// What <see cref="LafanBenchmarkRun.Execute"/> produced: the report, the statistics it used, and what was read and how
    /// fast. Built by the run and complete when it returns (every property is init-only).
    /// </summary>
    /// <param name="Folder">The folder the files came from.</param>
    /// <param name="Report">The metric totals per method and length, all finite.</param>
    /// <param name="Statistics">The statistics used: loaded, or computed from the training files.</param>
    public sealed record BenchmarkOutcome(LafanBenchmarkFolder Folder, BenchmarkReport Report, BenchmarkStatistics Statistics)
    {
        /// <summary>Test files read.</summary>
        public int TestFileCount { get; internal init; }

        /// <summary>Frames in all test files.</summary>
        public int TestFrames { get; internal init; }

        /// <summary>Bytes in all test files.</summary>
        public long TestBytes { get; internal init; }

        /// <summary>Training files the statistics were computed from; 0 when they were loaded.</summary>
        public int TrainingFileCount { get; internal init; }

        /// <summary>Seconds spent reading the test files.</summary>
        public double ReadSeconds { get; internal init; }

        /// <summary>Seconds spent reading the training files and computing statistics; 0 when they were loaded.</summary>
        public double StatisticsSeconds { get; internal init; }

        /// <summary>Seconds spent evaluating the windows.</summary>
        public double EvaluationSeconds { get; internal init; }

        /// <summary>
        /// Refuses statistics that are not finite before they are saved (a file that would poison every later
        /// run that loads it).
        /// </summary>
        /// <exception cref="DataFormatException">A mean, deviation or offset is not a finite number.</exception>
        public void RequireFiniteStatistics()
        {
            foreach (double[] values in new[] { Statistics.Mean, Statistics.StandardDeviation, Statistics.Offsets })
            {
                foreach (double v in values)
                {
                    if (!double.IsFinite(v))
                    {
                        throw new DataFormatException(Folder.Path, $"the statistics computed from the training files hold {v.ToString(CultureInfo.InvariantCulture)}", "expected finite motion values in the training files");
                    }
                }
            }
        }
    }
}
