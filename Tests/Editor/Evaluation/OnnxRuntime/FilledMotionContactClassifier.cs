using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Json;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 29's experimental contact classifier over a bake's filled motion (Python
    /// <c>deltainterp.contact_features</c>, its JSON from <c>classifier_document</c>), read here only to measure how
    /// the lockers do with its contacts (<see cref="FootContactMeasureTests"/>); nothing ships it. Features per filled
    /// frame and foot joint, in leg lengths: height over the joint's own ground level (5th percentile over the baked
    /// span), horizontal and vertical speed (central differences), the same foot's other joint, at the frames
    /// <c>offsets</c> around; the keys' heights and speeds around the gap, where the frame sits in it, the gap's length
    /// and whether the joint is a toe. A two-hidden-layer ReLU network, the same for every joint.
    /// </summary>
    internal sealed class FilledMotionContactClassifier
    {
        private static readonly int[] OtherJoint = { 1, 0, 3, 2 };
        private readonly int[] _offsets;
        private readonly double[] _mean, _scale;
        private readonly List<(double[] Weight, double[] Bias, int Inputs, int Outputs)> _layers = new List<(double[], double[], int, int)>();

        public FilledMotionContactClassifier(JsonValue doc)
        {
            double[] offsets = doc.ExpectMember("offsets").ExpectNumbers("offsets", -1);
            _offsets = Array.ConvertAll(offsets, o => (int)o);
            _mean = doc.ExpectMember("mean").ExpectNumbers("mean", -1);
            _scale = doc.ExpectMember("scale").ExpectNumbers("scale", _mean.Length);
            Threshold = doc.ExpectMember("threshold").ExpectNumber("threshold");
            foreach (JsonValue layer in doc.ExpectMember("layers").ExpectArray("layers"))
            {
                int inputs = (int)layer.ExpectMember("inputs").ExpectNumber("inputs"), outputs = (int)layer.ExpectMember("outputs").ExpectNumber("outputs");
                _layers.Add((layer.ExpectMember("weight").ExpectNumbers("weight", inputs * outputs), layer.ExpectMember("bias").ExpectNumbers("bias", outputs), inputs, outputs));
            }

            if (_layers[0].Inputs != _mean.Length || _mean.Length != 5 * _offsets.Length + 8) throw new ArgumentException("the classifier's inputs do not match its offsets", nameof(doc));
        }

        /// <summary>The probability at or above which a joint is planted (chosen on the validation tails).</summary>
        public double Threshold { get; }

        /// <summary>
        /// Frames × 4 probabilities (NaN on keys) for a baked span's foot joints (<paramref name="feet"/>: frames × 4 × 3,
        /// LeftFoot, LeftToe, RightFoot, RightToe), keys relative to its first frame.
        /// </summary>
        public float[] Probabilities(double[] feet, IReadOnlyList<int> keys, double legLength, double frameTime)
        {
            int frames = feet.Length / 12;
            double[] ground = Evaluation.Baking.FootSkating.GroundLevels(feet, 4);
            var rise = new double[frames * 4];
            var hspeed = new double[frames * 4];
            var vspeed = new double[frames * 4];
            for (int f = 0; f < frames; f++)
            {
                int before = Math.Max(f - 1, 0), after = Math.Min(f + 1, frames - 1);
                double step = Math.Max(after - before, 1) * frameTime;
                for (int k = 0; k < 4; k++)
                {
                    int a = (after * 4 + k) * 3, b = (before * 4 + k) * 3;
                    double dx = feet[a] - feet[b], dy = feet[a + 1] - feet[b + 1], dz = feet[a + 2] - feet[b + 2];
                    rise[f * 4 + k] = (feet[(f * 4 + k) * 3 + 1] - ground[k]) / legLength;
                    hspeed[f * 4 + k] = Math.Sqrt(dx * dx + dz * dz) / step / legLength;
                    vspeed[f * 4 + k] = dy / step / legLength;
                }
            }

            var result = new float[frames * 4];
            Array.Fill(result, float.NaN);
            var isKey = new bool[frames];
            foreach (int key in keys) isKey[key] = true;
            var x = new double[_mean.Length];
            int gap = 0;
            for (int f = 0; f < frames; f++)
            {
                if (isKey[f]) continue;
                while (gap + 2 < keys.Count && f >= keys[gap + 1]) gap++;
                int k0 = keys[gap], k1 = keys[gap + 1];
                double where = (double)(f - k0) / Math.Max(k1 - k0, 1);
                for (int c = 0; c < 4; c++)
                {
                    int o = OtherJoint[c], i = 0;
                    foreach (int s in _offsets)
                    {
                        int g = Math.Min(Math.Max(f + s, 0), frames - 1);
                        x[i++] = Math.Min(rise[g * 4 + c], 0.5);
                        x[i++] = Math.Min(hspeed[g * 4 + c], 5.0);
                        x[i++] = Math.Max(-3.0, Math.Min(vspeed[g * 4 + c], 3.0));
                        x[i++] = Math.Min(rise[g * 4 + o], 0.5);
                        x[i++] = Math.Min(hspeed[g * 4 + o], 5.0);
                    }

                    x[i++] = Math.Min(rise[k0 * 4 + c], 0.5);
                    x[i++] = Math.Min(rise[k1 * 4 + c], 0.5);
                    x[i++] = Math.Min(hspeed[k0 * 4 + c], 5.0);
                    x[i++] = Math.Min(hspeed[k1 * 4 + c], 5.0);
                    x[i++] = where;
                    x[i++] = 1 - where;
                    x[i++] = (k1 - k0) / 30.0;
                    x[i] = c % 2;
                    result[f * 4 + c] = (float)(1 / (1 + Math.Exp(-Forward(x))));
                }
            }

            return result;
        }

        private double Forward(double[] input)
        {
            var h = new double[input.Length];
            for (int i = 0; i < h.Length; i++) h[i] = ((float)input[i] - _mean[i]) / _scale[i]; // Python casts the features to float32
            for (int l = 0; l < _layers.Count; l++)
            {
                var (w, b, inputs, outputs) = _layers[l];
                var next = new double[outputs];
                for (int o = 0; o < outputs; o++)
                {
                    double sum = b[o];
                    for (int i = 0; i < inputs; i++) sum += w[o * inputs + i] * h[i];
                    next[o] = l + 1 < _layers.Count ? Math.Max(sum, 0) : sum;
                }

                h = next;
            }

            return h[0];
        }
    }
}
