using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Evaluation.Metrics;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The shipped model (Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx): it loads with its lazy graphs,
    /// lazy frames equal whole frames, and on the LaFAN1 benchmark it beats SLERP at 5, 15 and 30 frames
    /// in L2Q and L2P. Skips while the model is not exported yet or LaFAN1 is absent.
    /// </summary>
    [TestFixture]
    public sealed class ShippedModelTests
    {
        /// <summary>The default model (CMU) in <c>Runtime/Models</c>, found from the test assembly's folder upwards.</summary>
        internal static string RequireDefaultModel()
        {
            string? dir = AppContext.BaseDirectory;
            while (dir != null)
            {
                string candidate = Path.Combine(dir, ShippedModels.Default);
                if (File.Exists(candidate)) return candidate;
                dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
            }

            Assert.Ignore(ShippedModels.Default + " is not there; skipping.");
            return "";
        }

        /// <summary>The LaFAN1 model, the opt-in sample's (<see cref="ShippedModels.Lafan1"/>), found from the test assembly's folder upwards.</summary>
        internal static string RequireShippedModel()
        {
            string? dir = AppContext.BaseDirectory;
            while (dir != null)
            {
                string candidate = Path.Combine(dir, "Samples~", "LaFAN1Model", "DeltaInterpolator-LaFAN1.onnx");
                if (File.Exists(candidate)) return candidate;
                dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
            }

            Assert.Ignore("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx is not there yet (python3 -m deltainterp export --checkpoint Training/runs/runtime/checkpoint.pt --out Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx); skipping the shipped-model tests.");
            return "";
        }

        [Test]
        public void LoadsWithLazyGraphsAndLazyFramesEqualWholeFrames()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(RequireShippedModel(), requireLazy: true);
            Assert.That(model.Contract.JointCount, Is.EqualTo(22));
            GoldenCase c = Fixtures.Golden[2];
            Transition whole = c.ToTransition(model.Contract.Skeleton);
            model.Inbetween(whole);
            Transition lazy = c.ToTransition(model.Contract.Skeleton);
            LazyInbetweener lazyInbetweener = model.CreateLazy(c.PastFrames, c.MissingFrames);
            lazyInbetweener.Begin(lazy);
            for (int k = 0; k < c.MissingFrames; k++) lazyInbetweener.DecodeFrame(k);
            Assert.That(GoldenParityTests.MaxAbs(lazy.LocalRotations, whole.LocalRotations), Is.LessThan(1e-5));
            Assert.That(GoldenParityTests.MaxAbs(lazy.RootPositions, whole.RootPositions) * model.Contract.UnitScale, Is.LessThan(1e-5));
        }

        [Test]
        public void BeatsSlerpOnTheLafanBenchmark()
        {
            AssertBeatsSlerp(0);
        }

        /// <summary>
        /// The authoring case: a clip's first gap has one past key. Fed only the last of the 10 context frames
        /// (same windows and targets), the shipped model still beats SLERP in L2Q and L2P at 5, 15 and 30.
        /// </summary>
        [Test]
        public void BeatsSlerpWithOnePastKey()
        {
            AssertBeatsSlerp(1);
        }

        private static void AssertBeatsSlerp(int pastFrames)
        {
            string path = RequireShippedModel();
            string data = TestEnvironment.RequireLafan1();
            string stats = Path.Combine(data, "train_stats_official.json");
            if (!File.Exists(stats)) Assert.Ignore($"{stats} not found; skipping.");
            BvhAnimation[] clips = LafanDataset.ReadAll(LafanDataset.FindFiles(data, LafanDataset.TestSubjects));
            using Inbetweener model = OnnxRuntimeInbetweener.Load(path);
            var options = new BenchmarkOptions { Lengths = new[] { 5, 15, 30 }, FedPastFrames = pastFrames };
            BenchmarkReport report = LafanBenchmark.Run(clips, BenchmarkStatistics.Load(stats), new List<IInbetweener> { new SlerpBaseline(), model }, options);
            foreach (int n in options.Lengths)
            {
                MetricTotals m = report.Get("model", n), s = report.Get("slerp", n);
                TestContext.Out.WriteLine($"n = {n}: L2Q model {m.L2Q:F4} vs SLERP {s.L2Q:F4}; L2P model {m.L2P:F4} vs SLERP {s.L2P:F4}");
                Assert.That(m.L2Q, Is.LessThan(s.L2Q), $"L2Q at {n}");
                Assert.That(m.L2P, Is.LessThan(s.L2P), $"L2P at {n}");
            }
        }
    }
}
