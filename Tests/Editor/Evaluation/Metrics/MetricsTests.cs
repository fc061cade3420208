using System;
using DeltaInterpolator.Evaluation.Metrics;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Metrics
{
    public class MetricsTests
    {
        [Test]
        public void L2QTakesOneNormOverAllJointsOfAFrame()
        {
            // Two joints, each off by √2: the frame's error is √(2 + 2) = 2, not √2 + √2.
            double[] predicted = { 1, 0, 0, 0, 1, 0, 0, 0 };
            double[] truth = { 0, 1, 0, 0, 0, 0, 1, 0 };
            Assert.That(TransitionMetrics.SumL2Q(predicted, truth, 1, 2), Is.EqualTo(2.0).Within(1e-15));
            // Two frames of one joint: 0 and √2.
            double[] p2 = { 1, 0, 0, 0, 0, 1, 0, 0 };
            double[] t2 = { 1, 0, 0, 0, 1, 0, 0, 0 };
            Assert.That(TransitionMetrics.SumL2Q(p2, t2, 2, 1), Is.EqualTo(Math.Sqrt(2)).Within(1e-15));
        }

        [Test]
        public void L2PDividesEachCoordinateByItsStandardDeviation()
        {
            double[] std = { 2, 1, 1 };
            Assert.That(TransitionMetrics.SumL2P(new double[] { 2, 0, 0 }, new double[3], 1, 1, std), Is.EqualTo(1.0).Within(1e-15));
            Assert.That(TransitionMetrics.SumL2P(new double[] { 0, 3, 4, 0, 3, 4 }, new double[6], 2, 1, std), Is.EqualTo(10.0).Within(1e-15));
        }

        [Test]
        public void NpssMatchesAHandComputedExample()
        {
            // n = 2, D = 2. Feature 0: truth (1, 0) → Re DFT (1, 1) → power (1, 1) → CDF (½, 1), weight 2;
            // prediction (1, 1) → (2, 0) → (4, 0) → CDF (1, 1); EMD = ½.
            // Feature 1: truth (0, 1) → (1, −1) → CDF (½, 1), weight 2; prediction equal; EMD = 0.
            // NPSS = (½·2 + 0·2) / (2 + 2) = ¼.
            double[] truth = { 1, 0, 0, 1 };     // frames × features
            double[] predicted = { 1, 0, 1, 1 };
            Assert.That(new Npss(2, 2).Compute(truth, predicted), Is.EqualTo(0.25).Within(1e-15));
        }

        [Test]
        public void NpssOfIdenticalSequencesIsZeroAndOfAConstantPredictionIsPositive()
        {
            var random = new TestRandom(41);
            var truth = new double[15 * 3];
            for (int i = 0; i < truth.Length; i++) truth[i] = random.Gaussian();
            var npss = new Npss(15, 3);
            Assert.That(npss.Compute(truth, truth), Is.EqualTo(0).Within(1e-15));
            var constant = new double[truth.Length];
            for (int i = 0; i < constant.Length; i++) constant[i] = 0.5;
            Assert.That(npss.Compute(truth, constant), Is.GreaterThan(0.1));
        }

        /// <summary>A literal transcription of fast_npss with a full O(n²) DFT, to check the folded one.</summary>
        private static double ReferenceNpss(double[] truth, double[] predicted, int n, int features)
        {
            double emdSum = 0, weightSum = 0;
            for (int d = 0; d < features; d++)
            {
                double[] pt = Power(truth, n, features, d), pp = Power(predicted, n, features, d);
                double tt = 0, tp = 0;
                for (int k = 0; k < n; k++) { tt += pt[k]; tp += pp[k]; }
                double ct = 0, cp = 0, emd = 0;
                for (int k = 0; k < n; k++)
                {
                    ct += pt[k] / tt;
                    cp += pp[k] / tp;
                    emd += Math.Abs(cp - ct);
                }

                emdSum += emd * tt;
                weightSum += tt;
            }

            return emdSum / weightSum;
        }

        private static double[] Power(double[] series, int n, int features, int d)
        {
            var power = new double[n];
            for (int k = 0; k < n; k++)
            {
                double re = 0;
                for (int t = 0; t < n; t++) re += series[t * features + d] * Math.Cos(2 * Math.PI * k * t / n);
                power[k] = re * re;
            }

            return power;
        }

        [Test]
        public void NpssAgreesWithAFullDftForEveryLength([Values(1, 2, 3, 4, 5, 7, 15, 30, 45)] int n)
        {
            var random = new TestRandom(100 + n);
            const int features = 13; // not a multiple of the SIMD width
            var truth = new double[n * features];
            var predicted = new double[n * features];
            for (int i = 0; i < truth.Length; i++)
            {
                truth[i] = random.Gaussian() + 0.3;
                predicted[i] = truth[i] + 0.5 * random.Gaussian();
            }

            double expected = ReferenceNpss(truth, predicted, n, features);
            Assert.That(new Npss(n, features).Compute(truth, predicted), Is.EqualTo(expected).Within(1e-12 + 1e-10 * Math.Abs(expected)));
        }

        [Test]
        public void NpssAccumulatesOverSequencesWithPowerWeights()
        {
            var random = new TestRandom(43);
            var npss = new Npss(5, 2);
            double emd = 0, weight = 0, manualEmd = 0, manualWeight = 0;
            for (int s = 0; s < 3; s++)
            {
                var truth = new double[10];
                var predicted = new double[10];
                for (int i = 0; i < 10; i++) { truth[i] = random.Gaussian() * (s + 1); predicted[i] = random.Gaussian(); }
                npss.SetTruth(truth);
                npss.Accumulate(predicted, ref emd, ref weight);
                double one = ReferenceNpss(truth, predicted, 5, 2);
                double w = 0;
                for (int d = 0; d < 2; d++) foreach (double p in Power(truth, 5, 2, d)) w += p;
                manualEmd += one * w;
                manualWeight += w;
            }

            Assert.That(emd / weight, Is.EqualTo(manualEmd / manualWeight).Within(1e-12));
        }
    }
}
