using System;
using System.Diagnostics;

namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>
    /// Median, 95th percentile and sample count of repeated timings of one action, and the one rule by which
    /// every speed measurement is taken (<see cref="Measure"/>).
    /// </summary>
    public readonly struct Timing
    {
        /// <summary>Creates a timing from its statistics.</summary>
        public Timing(double median, double p95, int samples)
        {
            Median = median;
            P95 = p95;
            Samples = samples;
        }

        /// <summary>The median run, in the unit the measurement asked for.</summary>
        public double Median { get; }

        /// <summary>The 95th percentile run, in the same unit.</summary>
        public double P95 { get; }

        /// <summary>How many runs were timed.</summary>
        public int Samples { get; }

        /// <summary>
        /// Warm-up (a tenth of the repeats, at least 20 runs and 0.2 s), then up to
        /// <paramref name="repeats"/> timed runs within a 10 s budget (at least 10). The warm-up lets the JIT
        /// and the runtime's caches settle; the budget keeps a slow model from taking minutes per row.
        /// </summary>
        /// <param name="action">The work to time; called many times.</param>
        /// <param name="repeats">The most timed runs.</param>
        /// <param name="unitsPerSecond">1e3 for milliseconds, 1e6 for microseconds.</param>
        public static Timing Measure(Action action, int repeats, double unitsPerSecond)
        {
            var warm = Stopwatch.StartNew();
            for (int i = 0; i < Math.Max(20, repeats / 10) || warm.Elapsed.TotalSeconds < 0.2; i++) action();
            var samples = new double[repeats];
            int count = 0;
            var budget = Stopwatch.StartNew();
            while (count < repeats && (count < 10 || budget.Elapsed.TotalSeconds < 10))
            {
                long start = Stopwatch.GetTimestamp();
                action();
                samples[count++] = (Stopwatch.GetTimestamp() - start) * unitsPerSecond / Stopwatch.Frequency;
            }

            Array.Sort(samples, 0, count);
            double median = count % 2 == 1 ? samples[count / 2] : 0.5 * (samples[count / 2 - 1] + samples[count / 2]);
            double p95 = samples[Math.Min(count - 1, (int)Math.Ceiling(0.95 * count) - 1)];
            return new Timing(median, p95, count);
        }
    }
}
