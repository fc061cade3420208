using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Evaluation.Metrics;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>
    /// The benchmark as one use case on a <see cref="LafanBenchmarkFolder"/>: statistics loaded (or computed
    /// from the training files as the official code does), the test files read, every model refused before
    /// any work when it is for another skeleton, the windows scored by <see cref="LafanBenchmark"/>, and a
    /// result that is not a finite number refused (never a NaN in a table or a file). Front ends choose the
    /// methods and show the <see cref="BenchmarkOutcome"/>.
    /// </summary>
    public static class LafanBenchmarkRun
    {
        /// <summary>Window and offset of the official training statistics (get_train_stats).</summary>
        private const int StatisticsWindow = 50, StatisticsOffset = 20;

        /// <summary>Runs the benchmark; takes seconds to minutes.</summary>
        /// <param name="folder">The LaFAN1 files.</param>
        /// <param name="statisticsPath">A statistics JSON, or null to compute them from the training files.</param>
        /// <param name="methods">The in-betweeners to score, baselines and models.</param>
        /// <param name="options">Window layout and transition lengths, validated.</param>
        /// <param name="progress">Receives the reading and evaluating progress, or null.</param>
        /// <exception cref="DataFormatException">Files too short for a window, no training files to compute
        /// statistics from, a model for another skeleton, or a result that is not finite.</exception>
        public static BenchmarkOutcome Execute(
            LafanBenchmarkFolder folder,
            string? statisticsPath,
            IReadOnlyList<IInbetweener> methods,
            BenchmarkOptions options,
            IProgress<StageProgress>? progress)
        {
            long testBytes = folder.TestBytes();
            BenchmarkStatistics statistics;
            int trainingFileCount = 0;
            double statisticsSeconds = 0;
            if (statisticsPath != null)
            {
                statistics = BenchmarkStatistics.Load(statisticsPath);
            }
            else
            {
                var sw = Stopwatch.StartNew();
                if (folder.TrainingFiles.Count == 0)
                {
                    throw new DataFormatException(folder.Path, "no *_subject1..4.bvh training files to compute statistics from", "expected them in --data, or pass --stats FILE");
                }

                trainingFileCount = folder.TrainingFiles.Count;
                BvhAnimation[] training = LafanDataset.ReadAll(folder.TrainingFiles, progress, "Reading training files");
                RequireWindows(training, new BenchmarkOptions { Window = StatisticsWindow, Offset = StatisticsOffset }, folder.Path, "training files (subjects 1-4) for the statistics", "pass --stats FILE");
                statistics = BenchmarkStatistics.ComputeFromTraining(
                    training, options, StatisticsWindow, StatisticsOffset,
                    $"computed from {training.Length} training files in {folder.Path} (subjects 1-4, windows {StatisticsWindow}/{StatisticsOffset})", progress);
                statisticsSeconds = sw.Elapsed.TotalSeconds;
            }

            var read = Stopwatch.StartNew();
            BvhAnimation[] testClips = LafanDataset.ReadAll(folder.TestFiles, progress, "Reading test files");
            double readSeconds = read.Elapsed.TotalSeconds;
            RequireWindows(testClips, options, folder.Path, "test files (subject 5)", "a shorter --window");
            // Refuse a model for another skeleton before evaluating anything.
            foreach (IInbetweener method in methods)
            {
                if (method is Inbetweener model) model.Contract.CheckSkeleton(testClips[0].Skeleton, folder.TestFiles[0]);
            }

            var eval = Stopwatch.StartNew();
            BenchmarkReport report = LafanBenchmark.Run(testClips, statistics, methods, options, progress);
            double evaluationSeconds = eval.Elapsed.TotalSeconds;
            RequireFinite(report, folder.Path);
            int frames = 0;
            foreach (BvhAnimation clip in testClips) frames += clip.Motion.FrameCount;
            return new BenchmarkOutcome(folder, report, statistics)
            {
                TestFileCount = testClips.Length,
                TestFrames = frames,
                TestBytes = testBytes,
                TrainingFileCount = trainingFileCount,
                ReadSeconds = readSeconds,
                StatisticsSeconds = statisticsSeconds,
                EvaluationSeconds = evaluationSeconds,
            };
        }

        /// <summary>Refuses clips that hold no window (user input, not a bug: short files or a huge window).</summary>
        private static void RequireWindows(IReadOnlyList<BvhAnimation> clips, BenchmarkOptions options, string folder, string what, string remedy)
        {
            if (LafanBenchmark.CountWindows(clips, options) > 0) return;
            int longest = 0;
            foreach (BvhAnimation clip in clips) longest = Math.Max(longest, clip.Motion.FrameCount);
            throw new DataFormatException(folder,
                $"the {clips.Count} {what} are shorter than one window of {options.Window} frames (the longest has {longest:N0} frames; a window needs more than {options.Window})",
                $"expected longer files or {remedy}");
        }

        /// <summary>Refuses a report with a value that is not a finite number.</summary>
        private static void RequireFinite(BenchmarkReport report, string folder)
        {
            for (int m = 0; m < report.MethodIds.Count; m++)
            {
                foreach (int n in report.Lengths)
                {
                    MetricTotals t = report.Get(report.MethodIds[m], n);
                    foreach ((string metric, double value) in new[] { ("L2Q", t.L2Q), ("L2P", t.L2P), ("NPSS", t.Npss) })
                    {
                        if (!double.IsFinite(value))
                        {
                            throw new DataFormatException(folder,
                                $"{report.MethodNames[m]} {metric} at length {n} is {value.ToString(CultureInfo.InvariantCulture)}",
                                "expected finite results (motion values small enough for the metrics, e.g. |value| < 1e100)");
                        }
                    }
                }
            }
        }
    }
}
