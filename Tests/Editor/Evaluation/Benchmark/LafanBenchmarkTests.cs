using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using DeltaInterpolator.Core;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Evaluation.Metrics;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Benchmark
{
    public class LafanBenchmarkTests
    {
        [TestCase(100, 65, 40, new[] { 0 })]
        [TestCase(105, 65, 40, new[] { 0 })]            // 40 + 65 = 105 is not < 105: strict, as official
        [TestCase(106, 65, 40, new[] { 0, 40 })]
        [TestCase(65, 65, 40, new int[0])]
        [TestCase(200, 50, 20, new[] { 0, 20, 40, 60, 80, 100, 120, 140 })]
        public void WindowsStartWhileStartPlusWindowIsBelowTheFrameCount(int frames, int window, int offset, int[] expected)
        {
            Assert.That(LafanBenchmark.WindowStarts(frames, window, offset).ToArray(), Is.EqualTo(expected));
        }

        [Test]
        public void OptionsSayWhatToChange()
        {
            var options = new BenchmarkOptions { Window = 50 };
            Assert.That(() => options.Validate(), Throws.ArgumentException.With.Message.Contains("transition length 45 needs 56"));
            Assert.That(() => new BenchmarkOptions { Lengths = new[] { 5, 5 } }.Validate(), Throws.ArgumentException.With.Message.Contains("listed twice"));
            Assert.That(() => new BenchmarkOptions { Offset = 0 }.Validate(), Throws.ArgumentException.With.Message.Contains("offset"));
            Assert.That(() => new BenchmarkOptions().Validate(), Throws.Nothing);
        }

        /// <summary>
        /// A clip in which SLERP is exact: the root moves in a straight line at constant speed and every
        /// joint turns about a fixed axis at a constant rate (12° per frame, so the official
        /// near-parallel LERP fallback never triggers for the 5-frame gaps used).
        /// </summary>
        private static BvhAnimation LinearMotion(int frames)
        {
            var skeleton = new Skeleton(new[] { "Hips", "Spine", "Head" }, new[] { -1, 0, 1 }, new double[] { 0, 0, 0, 0, 10, 0, 0, 12, 0 });
            var positions = new double[frames * 9];
            var rotations = new double[frames * 12];
            var axes = new[] { new Vector3D(0.3, 0.9, 0.1), new Vector3D(1, 0, 0), new Vector3D(0, 0.6, 0.8) };
            var rates = new[] { 12.0, -12.0, 12.5 };
            for (int f = 0; f < frames; f++)
            {
                new Vector3D(100 + 2.0 * f, 90, -50 + 1.5 * f).Write(positions, f * 9);
                for (int j = 1; j < 3; j++) Vector3D.Read(skeleton.OffsetSpan, 3 * j).Write(positions, f * 9 + 3 * j);
                for (int j = 0; j < 3; j++)
                {
                    Vector3D a = (1 / axes[j].Length) * axes[j];
                    QuaternionD q = Quaternions.Multiply(Quaternions.FromAxisAngle(a, rates[j] * f * Math.PI / 180), Quaternions.FromAxisAngle(Vector3D.UnitZ, 0.4 * j));
                    q.Write(rotations, f * 12 + 4 * j);
                }
            }

            var motion = new MotionClip(skeleton, frames, 1.0 / 30, positions, rotations);
            var channels = Enumerable.Range(0, 3).Select(j => j == 0
                ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation }
                : new[] { BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation }).ToArray();
            return new BvhAnimation(motion, channels, null, "linear.bvh");
        }

        private static BenchmarkStatistics UnitStatistics(Skeleton skeleton)
        {
            var std = Enumerable.Repeat(10.0, 9).ToArray();
            return new BenchmarkStatistics(skeleton.Names, new double[9], std, skeleton.Offsets.ToArray(), "unit");
        }

        [Test]
        public void SlerpIsExactOnConstantVelocityMotionAndZeroVelocityIsNot()
        {
            BvhAnimation clip = LinearMotion(200);
            var options = new BenchmarkOptions { Window = 30, Offset = 17, Lengths = new[] { 1, 5 } };
            BenchmarkReport report = LafanBenchmark.Run(new[] { clip }, UnitStatistics(clip.Skeleton), new IInbetweener[] { new ZeroVelocityBaseline(), new SlerpBaseline() }, options);
            Assert.That(report.WindowCount, Is.EqualTo(LafanBenchmark.WindowStarts(200, 30, 17).Count()));
            foreach (int n in new[] { 1, 5 })
            {
                var slerp = report.Get("slerp", n);
                var zero = report.Get("zerovel", n);
                Assert.That(slerp.FrameCount, Is.EqualTo((long)report.WindowCount * n));
                Assert.That(slerp.L2Q, Is.LessThan(1e-12), $"slerp L2Q at {n}");
                Assert.That(slerp.L2P, Is.LessThan(1e-10), $"slerp L2P at {n}");
                Assert.That(slerp.Npss, Is.LessThan(1e-10), $"slerp NPSS at {n}");
                Assert.That(zero.L2Q, Is.GreaterThan(0.05), $"zero-velocity L2Q at {n}");
                Assert.That(zero.L2P, Is.GreaterThan(0.1), $"zero-velocity L2P at {n}");
            }

            Assert.That(report.Get("zerovel", 5).L2P, Is.GreaterThan(report.Get("zerovel", 1).L2P), "longer gaps drift further");
        }

        [Test]
        public void StatisticsFileErrorsNameTheFileAndLine()
        {
            string path = Path.Combine(Path.GetTempPath(), "deltainterp-stats-" + Guid.NewGuid().ToString("N") + ".json");
            try
            {
                File.WriteAllText(path, "{\n \"x_mean\": [0, 0, 0, 1, 1, 1],\n \"x_std\": [1, 1, 1, 1, 1],\n \"offsets\": [[0, 1, 0]]\n}\n");
                var e = Assert.Throws<DataFormatException>(() => BenchmarkStatistics.Load(path))!;
                Assert.That(e.Message, Does.StartWith(path + ":3: x_std has 5 values; expected 6"));

                File.WriteAllText(path, "{\n \"x_mean\": [0, 0, 0, 1, 1, 1],\n \"x_std\": [1, 1, 1, 1, 0, 1],\n \"offsets\": [[0, 1, 0]]\n}\n");
                e = Assert.Throws<DataFormatException>(() => BenchmarkStatistics.Load(path))!;
                Assert.That(e.Message, Does.Contain("x_std[4] is 0; expected positive"));

                File.WriteAllText(path, "{\n \"x_mean\": [0, 0, 0, 1, 1, 1],\n \"x_std\": [1, 1, 1, 1, 1, 1],\n \"offsets\": [[0, 1, 0]\n}\n");
                e = Assert.Throws<DataFormatException>(() => BenchmarkStatistics.Load(path))!;
                Assert.That(e.Line, Is.EqualTo(5));
                Assert.That(e.Message, Does.Contain("expected ',' or ']'"));

                File.WriteAllText(path, "{\n \"x_mean\": [0, 0, 0, 1, NaN, 1]\n}\n");
                e = Assert.Throws<DataFormatException>(() => BenchmarkStatistics.Load(path))!;
                Assert.That(e.Line, Is.EqualTo(2));

                File.WriteAllText(path, "{\n \"x_mean\": [0, 0, 0, 1, 1, 1],\n \"x_std\": [1, 1, 1, 1, 1, 1],\n \"offsets\": [[0, 1, 0]],\n \"joints\": [\"Hips\", \"Spine\"]\n}\n");
                BenchmarkStatistics ok = BenchmarkStatistics.Load(path);
                Assert.That(ok.Offsets, Is.EqualTo(new double[] { 0, 0, 0, 0, 1, 0 }));
                var wrong = new Skeleton(new[] { "Hips", "Chest" }, new[] { -1, 0 }, new double[6]);
                e = Assert.Throws<DataFormatException>(() => ok.SkeletonFor(wrong, "x.bvh"))!;
                Assert.That(e.Message, Does.Contain("joint 1 is 'Spine' in the statistics but 'Chest' in x.bvh"));

                // What ToJson writes, Load reads back.
                File.WriteAllText(path, ok.ToJson());
                BenchmarkStatistics again = BenchmarkStatistics.Load(path);
                Assert.That(again.StandardDeviation, Is.EqualTo(ok.StandardDeviation));
                Assert.That(again.JointNames, Is.EqualTo(ok.JointNames));
            }
            finally
            {
                File.Delete(path);
            }
        }

        /// <summary>
        /// The official benchmark on the 27 available LaFAN1 files with the official statistics
        /// (method-spec §1.12): 376 windows; L2Q and L2P to 4 decimals, NPSS to 5, as printed there.
        /// </summary>
        [Test]
        public void ReproducesTheOfficialBenchmarkOnTheSharedLafan1Files()
        {
            string dir = TestEnvironment.RequireLafan1();
            string statsPath = Path.Combine(dir, "train_stats_official.json");
            if (!File.Exists(statsPath)) Assert.Ignore($"{statsPath} not found; skipping.");
            BvhAnimation[] clips = LafanDataset.ReadAll(LafanDataset.FindFiles(dir, LafanDataset.TestSubjects));
            BenchmarkReport report = LafanBenchmark.Run(clips, BenchmarkStatistics.Load(statsPath), new IInbetweener[] { new ZeroVelocityBaseline(), new SlerpBaseline() }, new BenchmarkOptions());
            Assert.That(report.WindowCount, Is.EqualTo(376));
            var expected = new Dictionary<string, double[][]>
            {
                // L2Q, L2P, NPSS at 5/15/30/45
                ["zerovel"] = new[] { new[] { 0.4867, 1.0060, 1.4660, 1.7823 }, new[] { 1.1992, 2.9213, 5.1748, 7.2551 }, new[] { 0.00387, 0.03991, 0.19049, 0.43772 } },
                ["slerp"] = new[] { new[] { 0.1797, 0.5236, 0.8657, 1.0919 }, new[] { 0.2854, 1.0293, 2.0595, 2.9918 }, new[] { 0.00162, 0.02839, 0.15522, 0.37231 } },
            };
            int[] lengths = { 5, 15, 30, 45 };
            foreach (var method in expected)
            {
                for (int l = 0; l < 4; l++)
                {
                    var totals = report.Get(method.Key, lengths[l]);
                    CheckPrinted(totals.L2Q, method.Value[0][l], 4, $"{method.Key} L2Q@{lengths[l]}");
                    CheckPrinted(totals.L2P, method.Value[1][l], 4, $"{method.Key} L2P@{lengths[l]}");
                    CheckPrinted(totals.Npss, method.Value[2][l], 5, $"{method.Key} NPSS@{lengths[l]}");
                }
            }

            // The extra foot-skating table: every method is scored on the ground truth's planted samples, and the truth's
            // own skating (below the contact speed by definition) lies under SLERP's, which slides a stance foot.
            foreach (int n in lengths)
            {
                MetricTotals truth = report.GroundTruth(n), slerp = report.Get("slerp", n), zero = report.Get("zerovel", n);
                TestContext.WriteLine($"foot skating at {n}: truth {truth.FootSkating:F4}, SLERP {slerp.FootSkating:F4}, zero-velocity {zero.FootSkating:F4} leg lengths/s over {truth.FootContactSamples} samples");
                Assert.That(truth.FootContactSamples, Is.GreaterThan(100 * n), $"planted samples at {n}");
                Assert.That(slerp.FootContactSamples, Is.EqualTo(truth.FootContactSamples));
                Assert.That(zero.FootContactSamples, Is.EqualTo(truth.FootContactSamples));
                Assert.That(truth.FootSkating, Is.GreaterThan(0).And.LessThan(FootSkating.ContactSpeed));
                Assert.That(slerp.FootSkating, Is.GreaterThan(truth.FootSkating));
            }
        }

        /// <summary>Agreement to the reference's printed digits: within half a unit of its last decimal.</summary>
        private static void CheckPrinted(double actual, double reference, int decimals, string what)
        {
            double halfLastDigit = 0.5 * Math.Pow(10, -decimals) * (1 + 1e-9);
            Assert.That(actual, Is.EqualTo(reference).Within(halfLastDigit), what);
        }

        [Test]
        public void StatisticsFromTheTrainingFilesAreCentredAndFacePlusX()
        {
            string dir = TestEnvironment.RequireLafan1();
            IReadOnlyList<string> files = LafanDataset.FindFiles(dir, LafanDataset.TrainingSubjects);
            if (files.Count == 0) Assert.Ignore("no training files (subjects 1-4) found; skipping.");
            BenchmarkStatistics stats = BenchmarkStatistics.ComputeFromTraining(LafanDataset.ReadAll(files), new BenchmarkOptions());
            Assert.That(stats.JointCount, Is.EqualTo(22));
            Assert.That(stats.Mean[0], Is.EqualTo(0).Within(1e-9), "root x mean: windows are centred");
            Assert.That(stats.Mean[2], Is.EqualTo(0).Within(1e-9), "root z mean: windows are centred");
            int head = Array.IndexOf(stats.JointNames!.ToArray(), "Head");
            Assert.That(stats.Mean[3 * head], Is.GreaterThan(5), "the head leans ahead: the character faces +X");
            Assert.That(stats.Mean[3 * head + 1], Is.InRange(100, 160), "head height in cm (this subset has much floor work: ~118; official full set: 136)");
            Assert.That(stats.StandardDeviation.Min(), Is.GreaterThan(10));
        }
    }
}
