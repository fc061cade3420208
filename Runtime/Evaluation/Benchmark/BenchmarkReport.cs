using System.Collections.Generic;
using DeltaInterpolator.Evaluation.Metrics;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>The result of one benchmark run: metric totals per method and transition length.</summary>
    public sealed class BenchmarkReport
    {
        private readonly MetricTotals[][] _totals;
        private readonly MetricTotals[] _groundTruth;

        internal BenchmarkReport(
            int windowCount,
            BenchmarkOptions options,
            string statisticsSource,
            IReadOnlyList<string> methodIds,
            IReadOnlyList<string> methodNames,
            MetricTotals[][] totals,
            MetricTotals[] groundTruth)
        {
            WindowCount = windowCount;
            Window = options.Window;
            Offset = options.Offset;
            PastFrames = options.PastFrames;
            FedPastFrames = options.EffectivePastFrames;
            ShortContext = options.ShortContext;
            Lengths = new List<int>(options.Lengths).ToArray();
            StatisticsSource = statisticsSource;
            MethodIds = methodIds;
            MethodNames = methodNames;
            _totals = totals;
            _groundTruth = groundTruth;
        }

        /// <summary>Number of test windows evaluated.</summary>
        public int WindowCount { get; }

        /// <summary>Frames per window.</summary>
        public int Window { get; }

        /// <summary>Frames between window starts.</summary>
        public int Offset { get; }

        /// <summary>Past key frames.</summary>
        public int PastFrames { get; }

        /// <summary>How many of the context frames the in-betweeners were given (the last ones).</summary>
        public int FedPastFrames { get; }

        /// <summary>How fewer fed frames than <see cref="PastFrames"/> were laid out as past keys.</summary>
        public Core.Inbetweening.ShortContextPolicy ShortContext { get; }

        /// <summary>Transition lengths, in the order evaluated.</summary>
        public IReadOnlyList<int> Lengths { get; }

        /// <summary>Where the statistics came from.</summary>
        public string StatisticsSource { get; }

        /// <summary>Method keys (<see cref="Core.Inbetweening.IInbetweener.Id"/>), in the order evaluated.</summary>
        public IReadOnlyList<string> MethodIds { get; }

        /// <summary>Method display names, parallel to <see cref="MethodIds"/>.</summary>
        public IReadOnlyList<string> MethodNames { get; }

        /// <summary>The totals of method <paramref name="methodId"/> at transition length <paramref name="length"/>.</summary>
        /// <exception cref="KeyNotFoundException">No such method or length in this report.</exception>
        public MetricTotals Get(string methodId, int length)
        {
            int m = -1;
            for (int i = 0; i < MethodIds.Count; i++) if (MethodIds[i] == methodId) m = i;
            int l = -1;
            for (int i = 0; i < Lengths.Count; i++) if (Lengths[i] == length) l = i;
            if (m < 0 || l < 0) throw new KeyNotFoundException($"no result for method '{methodId}' at length {length}");
            return _totals[m][l];
        }

        /// <summary>
        /// The ground truth scored as a method at <paramref name="length"/>: only its foot skating is set (the
        /// floor no method can beat: motion capture's planted feet creep a little).
        /// </summary>
        /// <exception cref="KeyNotFoundException">No such length in this report.</exception>
        public MetricTotals GroundTruth(int length)
        {
            for (int i = 0; i < Lengths.Count; i++) if (Lengths[i] == length) return _groundTruth[i];
            throw new KeyNotFoundException($"no result at length {length}");
        }
    }
}
