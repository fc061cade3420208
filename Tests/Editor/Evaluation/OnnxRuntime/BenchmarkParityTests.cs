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
    /// The C# benchmark's model row equals Python's <c>evaluate --checkpoint</c> on the same weights to
    /// 1e-3 at every length: for the tiny fixture (Tests/Fixtures~/tiny-model.benchmark.json, from
    /// tiny-model.pt) and for the shipped model (Tests/Fixtures~/shipped-model.benchmark.json, from the
    /// checkpoint it was exported from). Needs LaFAN1 (skips without it).
    /// </summary>
    [TestFixture]
    public sealed class BenchmarkParityTests
    {
        private const double Tolerance = 1e-3;

        [Test]
        public void TinyModelRowEqualsPythonEvaluate()
        {
            AssertModelRowEqualsPython(Fixtures.TinyModel, Path.Combine(Fixtures.Directory, "tiny-model.benchmark.json"));
        }

        [Test]
        public void ShippedModelRowEqualsPythonEvaluate()
        {
            AssertModelRowEqualsPython(ShippedModelTests.RequireShippedModel(), Path.Combine(Fixtures.Directory, "shipped-model.benchmark.json"));
        }

        /// <summary>
        /// Sparse keys (issue: a model for authoring): with only the last P of the 10 context frames fed,
        /// the C# row still equals Python's <c>evaluate --past-frames P</c> (fixtures written from the
        /// checkpoint the shipped model was exported from).
        /// </summary>
        [TestCase(1)]
        [TestCase(5)]
        public void ShippedModelRowWithFewerPastFramesEqualsPythonEvaluate(int pastFrames)
        {
            AssertModelRowEqualsPython(ShippedModelTests.RequireShippedModel(),
                Path.Combine(Fixtures.Directory, $"shipped-model.p{pastFrames}.benchmark.json"), pastFrames);
        }

        private static void AssertModelRowEqualsPython(string modelPath, string expectedPath, int pastFrames = 0)
        {
            string data = TestEnvironment.RequireLafan1();
            string stats = Path.Combine(data, "train_stats_official.json");
            if (!File.Exists(stats)) Assert.Ignore($"{stats} not found; skipping the benchmark parity test.");
            JsonValue document = JsonValue.Parse(File.ReadAllText(expectedPath), expectedPath);
            JsonValue expected = document.ExpectMember("results").ExpectMember("model");
            int expectedPast = pastFrames == 0 ? 10 : pastFrames;
            IReadOnlyDictionary<string, JsonValue> top = document.ExpectObject("benchmark results");
            Assert.That(top.TryGetValue("past_frames", out JsonValue? past) ? (int)past.ExpectNumber("past_frames") : 10, Is.EqualTo(expectedPast), $"{expectedPath} was written for another --past-frames");

            BvhAnimation[] clips = LafanDataset.ReadAll(LafanDataset.FindFiles(data, LafanDataset.TestSubjects));
            using Inbetweener model = OnnxRuntimeInbetweener.Load(modelPath);
            var options = new BenchmarkOptions { FedPastFrames = pastFrames };
            BenchmarkReport report = LafanBenchmark.Run(clips, BenchmarkStatistics.Load(stats), new List<IInbetweener> { model }, options);

            foreach (int n in options.Lengths)
            {
                MetricTotals t = report.Get("model", n);
                string key = n.ToString(System.Globalization.CultureInfo.InvariantCulture);
                double l2q = expected.ExpectMember("l2q").ExpectMember(key).ExpectNumber("l2q");
                double l2p = expected.ExpectMember("l2p").ExpectMember(key).ExpectNumber("l2p");
                double npss = expected.ExpectMember("npss").ExpectMember(key).ExpectNumber("npss");
                TestContext.Out.WriteLine($"n = {n}: L2Q {t.L2Q:F6} vs {l2q:F6}, L2P {t.L2P:F6} vs {l2p:F6}, NPSS {t.Npss:F6} vs {npss:F6}");
                Assert.That(t.L2Q, Is.EqualTo(l2q).Within(Tolerance), $"L2Q at {n}");
                Assert.That(t.L2P, Is.EqualTo(l2p).Within(Tolerance), $"L2P at {n}");
                Assert.That(t.Npss, Is.EqualTo(npss).Within(Tolerance), $"NPSS at {n}");
            }
        }
    }
}
