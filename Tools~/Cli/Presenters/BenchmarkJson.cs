using System;
using System.Globalization;
using System.IO;
using System.Text.Json;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Evaluation.Metrics;

namespace DeltaInterpolator.Cli.Presenters
{
    /// <summary>
    /// The benchmark's results as the JSON of its <c>--json</c> help: {"windows", "window", "offset", "stats",
    /// "past_frames", "past_policy", "results": {method: {l2q|l2p|npss: {length: value}}}}.
    /// </summary>
    internal static class BenchmarkJson
    {
        /// <summary>Writes the file whole or not at all (see <see cref="OutputFile.Write"/>).</summary>
        public static void Write(string path, BenchmarkReport report, string statsSource)
        {
            OutputFile.Write(path, stream => Write(stream, report, statsSource));
        }

        /// <summary>The results as JSON (a throw half-way leaves the target untouched: see <see cref="OutputFile.Write"/>).</summary>
        public static void Write(Stream stream, BenchmarkReport report, string statsSource)
        {
            using var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true });
            w.WriteStartObject();
            w.WriteNumber("windows", report.WindowCount);
            w.WriteNumber("window", report.Window);
            w.WriteNumber("offset", report.Offset);
            w.WriteString("stats", statsSource);
            w.WriteNumber("past_frames", report.FedPastFrames);
            w.WriteString("past_policy", report.ShortContext == ShortContextPolicy.RepeatEarliest ? "repeat" : "feed");
            w.WriteStartObject("results");
            for (int m = 0; m < report.MethodIds.Count; m++)
            {
                string id = report.MethodIds[m];
                w.WriteStartObject(id);
                WriteMetric(w, report, id, "l2q", t => t.L2Q);
                WriteMetric(w, report, id, "l2p", t => t.L2P);
                WriteMetric(w, report, id, "npss", t => t.Npss);
                WriteMetric(w, report, id, "foot_skating", t => t.FootSkating);
                w.WriteEndObject();
            }

            w.WriteEndObject();
            // Not an official metric: the ground truth's own foot skating, the floor of "foot_skating".
            w.WriteStartObject("ground_truth_foot_skating");
            foreach (int n in report.Lengths) WriteNumberOrNull(w, n.ToString(CultureInfo.InvariantCulture), report.GroundTruth(n).FootSkating);
            w.WriteEndObject();
            w.WriteEndObject();
        }

        private static void WriteMetric(Utf8JsonWriter w, BenchmarkReport report, string id, string name, Func<MetricTotals, double> value)
        {
            w.WriteStartObject(name);
            foreach (int n in report.Lengths) WriteNumberOrNull(w, n.ToString(CultureInfo.InvariantCulture), value(report.Get(id, n)));
            w.WriteEndObject();
        }

        // Foot skating has no value where no window has a planted ground-truth foot: null, not NaN (invalid JSON).
        private static void WriteNumberOrNull(Utf8JsonWriter w, string name, double value)
        {
            if (double.IsFinite(value)) w.WriteNumber(name, value);
            else w.WriteNull(name);
        }
    }
}
