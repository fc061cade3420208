using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Json;
using DeltaInterpolator.Evaluation.Metrics;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// <c>benchmark --past-frames P</c>: at P = 10 every row equals the results recorded before the option
    /// existed (Tests/Fixtures~/tiny-model.benchmark.json, Python's evaluate, to 1e-3) under either policy;
    /// SLERP and zero-velocity do not change with P or the policy; the model does, and gets P + 1 key
    /// frames (feed) or 11 (repeat). Needs LaFAN1 (skips without it).
    /// </summary>
    [TestFixture]
    public sealed class PastFramesBenchmarkTests
    {
        private static readonly int[] Lengths = { 5, 15, 30, 45 };

        [Test]
        public void PastFramesTenEqualsTheRecordedResultsAndBaselinesIgnoreP()
        {
            string data = TestEnvironment.RequireLafan1();
            string stats = Path.Combine(data, "train_stats_official.json");
            if (!File.Exists(stats)) Assert.Ignore($"{stats} not found; skipping.");
            BvhAnimation[] clips = LafanDataset.ReadAll(LafanDataset.FindFiles(data, LafanDataset.TestSubjects));
            BenchmarkStatistics statistics = BenchmarkStatistics.Load(stats);
            string expectedPath = Path.Combine(Fixtures.Directory, "tiny-model.benchmark.json");
            JsonValue expected = JsonValue.Parse(File.ReadAllText(expectedPath), expectedPath).ExpectMember("results");
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            int featureSize = model.Contract.KeyFeatureSize;
            var methods = new List<IInbetweener> { new ZeroVelocityBaseline(), new SlerpBaseline(), model };

            BenchmarkReport Run(int p, ShortContextPolicy policy, int[] lengths) => LafanBenchmark.Run(clips, statistics, methods,
                new BenchmarkOptions { Lengths = lengths, FedPastFrames = p, ShortContext = policy });

            BenchmarkReport reference = Run(10, ShortContextPolicy.FeedAvailable, Lengths);
            foreach (string id in new[] { "zerovel", "slerp", "model" })
            {
                foreach (int n in Lengths)
                {
                    string key = n.ToString(System.Globalization.CultureInfo.InvariantCulture);
                    MetricTotals t = reference.Get(id, n);
                    Assert.That(t.L2Q, Is.EqualTo(expected.ExpectMember(id).ExpectMember("l2q").ExpectMember(key).ExpectNumber("l2q")).Within(1e-3), $"{id} L2Q at {n}");
                    Assert.That(t.L2P, Is.EqualTo(expected.ExpectMember(id).ExpectMember("l2p").ExpectMember(key).ExpectNumber("l2p")).Within(1e-3), $"{id} L2P at {n}");
                }
            }

            AssertSameRow(Run(10, ShortContextPolicy.RepeatEarliest, Lengths), reference, "model", "P = 10 repeat");

            foreach (int p in new[] { 1, 5 })
            {
                foreach (ShortContextPolicy policy in new[] { ShortContextPolicy.FeedAvailable, ShortContextPolicy.RepeatEarliest })
                {
                    // Two lengths keep the test short; rows are per length, so they compare with the reference's.
                    BenchmarkReport report = Run(p, policy, new[] { 5, 30 });
                    string what = $"P = {p} {policy}";
                    AssertSameRow(report, reference, "zerovel", what);
                    AssertSameRow(report, reference, "slerp", what);
                    Assert.That(report.Get("model", 30).L2P, Is.Not.EqualTo(reference.Get("model", 30).L2P), what + ": the model sees less context");
                    int keys = policy == ShortContextPolicy.FeedAvailable ? p + 1 : 11;
                    Assert.That(model.LastKeyFeatures.Length, Is.EqualTo(keys * featureSize), what + ": key frames fed");
                    TestContext.Out.WriteLine($"{what}: model L2P at 30 = {report.Get("model", 30).L2P:F4} (P = 10: {reference.Get("model", 30).L2P:F4})");
                }
            }
        }

        private static void AssertSameRow(BenchmarkReport actual, BenchmarkReport expected, string id, string what)
        {
            foreach (int n in actual.Lengths)
            {
                MetricTotals a = actual.Get(id, n), e = expected.Get(id, n);
                Assert.That(a.L2Q, Is.EqualTo(e.L2Q), $"{what}: {id} L2Q at {n}");
                Assert.That(a.L2P, Is.EqualTo(e.L2P), $"{what}: {id} L2P at {n}");
                Assert.That(a.Npss, Is.EqualTo(e.Npss), $"{what}: {id} NPSS at {n}");
            }
        }
    }
}
