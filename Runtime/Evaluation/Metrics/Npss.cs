using System;
using System.Numerics;
using System.Runtime.InteropServices;

namespace DeltaInterpolator.Evaluation.Metrics
{
    /// <summary>
    /// Normalised Power Spectrum Similarity exactly as the official <c>fast_npss</c> computes it, for
    /// sequences of a fixed length n and D features (frames × features, e.g. global quaternions
    /// flattened to joints × 4):
    /// F = Re(DFT over time) — the real part of the full n-point DFT, not its magnitude; power P = F²;
    /// per feature, P is divided by its total and accumulated over frequency into a CDF; the EMD is
    /// the L1 distance of the two CDFs; features and sequences are averaged with the ground truth's
    /// total power as weight. Use one instance per length; <see cref="SetTruth"/> once per sequence,
    /// then <see cref="Accumulate"/> once per method.
    /// </summary>
    /// <remarks>
    /// n ≤ 45 in the benchmark, so a direct DFT with a precomputed cosine table beats an FFT. Only the
    /// frequencies 0..n/2 are computed (Re F_k = Re F_{n−k} for real input) and frames t and n − t are
    /// summed before multiplying (their cosines are equal), a quarter of the naive work.
    /// Where the official code would return NaN (a feature with zero total power), a zero-weight
    /// ground-truth feature is skipped and a zero-power prediction counts as an all-zero CDF.
    /// </remarks>
    public sealed class Npss
    {
        private readonly int _n;
        private readonly int _features;
        private readonly double[] _cos;        // (n/2 + 1) × (n/2 + 1): cos(2πkt/n)
        private readonly double[] _folded;     // (n/2 + 1) × features, scratch
        private readonly double[] _truthCdf;   // n × features
        private readonly double[] _truthTotal; // features
        private readonly double[] _spectrum;   // n × features, scratch for the prediction's CDF
        private readonly double[] _predictedTotal; // features, scratch
        private readonly double[] _inverse;        // features, scratch
        private bool _hasTruth;

        /// <summary>Creates the metric for sequences of <paramref name="frameCount"/> frames and <paramref name="featureCount"/> features.</summary>
        public Npss(int frameCount, int featureCount)
        {
            if (frameCount < 1) throw new ArgumentOutOfRangeException(nameof(frameCount), "at least one frame is needed");
            if (featureCount < 1) throw new ArgumentOutOfRangeException(nameof(featureCount), "at least one feature is needed");
            _n = frameCount;
            _features = featureCount;
            int half = frameCount / 2;
            _cos = new double[(half + 1) * (half + 1)];
            for (int k = 0; k <= half; k++)
            {
                for (int t = 0; t <= half; t++)
                {
                    // Reduce k·t modulo n first so the angle stays small and exact.
                    _cos[k * (half + 1) + t] = Math.Cos(2.0 * Math.PI * ((long)k * t % frameCount) / frameCount);
                }
            }

            _truthCdf = new double[frameCount * featureCount];
            _truthTotal = new double[featureCount];
            _spectrum = new double[frameCount * featureCount];
            _predictedTotal = new double[featureCount];
            _inverse = new double[featureCount];
            _folded = new double[(half + 1) * featureCount];
        }

        /// <summary>Sequence length n.</summary>
        public int FrameCount => _n;

        /// <summary>Number of features D.</summary>
        public int FeatureCount => _features;

        /// <summary>Sets the ground-truth sequence (frames × features) that the next calls compare with.</summary>
        public void SetTruth(ReadOnlySpan<double> truth)
        {
            NormalizedCdf(truth, _truthCdf, _truthTotal);
            _hasTruth = true;
        }

        /// <summary>
        /// Adds Σ_d EMD_d · W_d and Σ_d W_d of <paramref name="predicted"/> against the current truth to
        /// <paramref name="weightedEmdSum"/> and <paramref name="weightSum"/>; NPSS = their ratio.
        /// </summary>
        public void Accumulate(ReadOnlySpan<double> predicted, ref double weightedEmdSum, ref double weightSum)
        {
            if (!_hasTruth) throw new InvalidOperationException("call SetTruth before Accumulate");
            double[] predictedCdf = _spectrum;
            NormalizedCdf(predicted, predictedCdf, _predictedTotal);
            int n = _n, D = _features;
            double[] emd = _predictedTotal; // reused as per-feature EMD accumulator
            Array.Clear(emd, 0, D);
            int width = Vector<double>.Count;
            int vectorEnd = D - D % width;
            for (int k = 0; k < n; k++)
            {
                int row = k * D;
                int d = 0;
                for (; d < vectorEnd; d += width)
                {
                    (new Vector<double>(emd, d) + Vector.Abs(new Vector<double>(predictedCdf, row + d) - new Vector<double>(_truthCdf, row + d))).CopyTo(emd, d);
                }

                for (; d < D; d++) emd[d] += Math.Abs(predictedCdf[row + d] - _truthCdf[row + d]);
            }

            for (int d = 0; d < D; d++)
            {
                double weight = _truthTotal[d];
                if (weight == 0) continue;
                weightedEmdSum += emd[d] * weight;
                weightSum += weight;
            }
        }

        /// <summary>NPSS of one prediction against one truth (convenience for tests and small inputs).</summary>
        public double Compute(ReadOnlySpan<double> truth, ReadOnlySpan<double> predicted)
        {
            SetTruth(truth);
            double emd = 0, weight = 0;
            Accumulate(predicted, ref emd, ref weight);
            return emd / weight;
        }

        /// <summary>destination[i] += source[i], vectorised.</summary>
        private static void AddInto(Span<double> destination, ReadOnlySpan<double> source)
        {
            int width = Vector<double>.Count;
            int i = 0;
            if (destination.Length >= width)
            {
                Span<Vector<double>> dv = MemoryMarshal.Cast<double, Vector<double>>(destination);
                ReadOnlySpan<Vector<double>> sv = MemoryMarshal.Cast<double, Vector<double>>(source.Slice(0, destination.Length));
                for (int v = 0; v < dv.Length; v++) dv[v] += sv[v];
                i = dv.Length * width;
            }

            for (; i < destination.Length; i++) destination[i] += source[i];
        }

        private static void AddInto(double[] destination, int destinationIndex, double[] source, int sourceIndex, int count)
        {
            AddInto(destination.AsSpan(destinationIndex, count), source.AsSpan(sourceIndex, count));
        }

        private void NormalizedCdf(ReadOnlySpan<double> series, double[] cdf, double[] totals)
        {
            int n = _n, D = _features;
            if (series.Length < n * D) throw new ArgumentException($"expected {n} frames × {D} features", nameof(series));
            int half = n / 2;

            // cos(2πk(n−t)/n) = cos(2πkt/n): fold frames t and n−t together first, which halves the DFT.
            double[] folded = _folded;
            series.Slice(0, D).CopyTo(folded.AsSpan(0, D));
            for (int t = 1; t <= half; t++)
            {
                ReadOnlySpan<double> a = series.Slice(t * D, D);
                Span<double> dst = folded.AsSpan(t * D, D);
                if (n - t == t)
                {
                    a.CopyTo(dst);
                }
                else
                {
                    ReadOnlySpan<double> b = series.Slice((n - t) * D, D);
                    a.CopyTo(dst);
                    AddInto(dst, b);
                }
            }

            // Power spectrum for k = 0..n/2, vectorised over features with the sum kept in a register;
            // the upper half mirrors it.
            int width = Vector<double>.Count;
            int vectorEnd = D - D % width;
            for (int k = 0; k <= half; k++)
            {
                int row = k * D;
                int cosRow = k * (half + 1);
                for (int d = 0; d < vectorEnd; d += width)
                {
                    Vector<double> sum = Vector<double>.Zero;
                    for (int t = 0; t <= half; t++)
                    {
                        sum += new Vector<double>(_cos[cosRow + t]) * new Vector<double>(folded, t * D + d);
                    }

                    (sum * sum).CopyTo(cdf, row + d);
                }

                for (int d = vectorEnd; d < D; d++)
                {
                    double sum = 0;
                    for (int t = 0; t <= half; t++) sum += _cos[cosRow + t] * folded[t * D + d];
                    cdf[row + d] = sum * sum;
                }
            }

            for (int k = half + 1; k < n; k++)
            {
                Array.Copy(cdf, (n - k) * D, cdf, k * D, D);
            }

            Array.Clear(totals, 0, D);
            for (int k = 0; k < n; k++) AddInto(totals, 0, cdf, k * D, D);

            // Normalise by the total (a zero-power feature gets an all-zero CDF) and accumulate over k.
            double[] inverse = _inverse;
            for (int d = 0; d < D; d++) inverse[d] = totals[d] > 0 ? 1.0 / totals[d] : 0.0;
            for (int d = 0; d < D; d++) cdf[d] *= inverse[d];
            for (int k = 1; k < n; k++)
            {
                int row = k * D, previous = row - D;
                int d = 0;
                for (; d < vectorEnd; d += width)
                {
                    (new Vector<double>(cdf, previous + d) + new Vector<double>(cdf, row + d) * new Vector<double>(inverse, d)).CopyTo(cdf, row + d);
                }

                for (; d < D; d++) cdf[row + d] = cdf[previous + d] + cdf[row + d] * inverse[d];
            }
        }
    }
}
