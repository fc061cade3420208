using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Clips
{
    public static partial class KeyFill
    {
        /// <summary>
        /// The fill of a humanoid clip: <paramref name="recorded"/> (the bake's frames from the first to the last key as a
        /// humanoid clip's curves, one key per frame: the humanoid recording path, <see cref="HumanoidCurves.Build"/>)
        /// written as keys on the clip's body and muscle curves, the body rotation kept in the hemisphere of the frame before.
        /// </summary>
        /// <exception cref="KeyFillException">The clip keys a body or muscle curve the recording lacks, or part of the body rotation.</exception>
        /// <exception cref="ArgumentException">The recording does not span the plan's keys.</exception>
        public static KeyFillEdit Edit(KeyFillPlan plan, IReadOnlyList<KeyedCurve> curves, IReadOnlyList<ClipCurve> recorded)
        {
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            if (curves == null) throw new ArgumentNullException(nameof(curves));
            if (recorded == null) throw new ArgumentNullException(nameof(recorded));
            if (plan.Kind != KeyFillClipKind.Humanoid) throw new ArgumentException($"{plan.Clip} is a transform clip; fill it from the baked motion", nameof(plan));
            CheckSameCurves(plan, curves);
            int span = plan.LastKey - plan.FirstKey + 1;
            var byProperty = new Dictionary<string, ClipCurve>(StringComparer.Ordinal);
            foreach (ClipCurve c in recorded)
            {
                if (c.KeyCount != span) throw new ArgumentException($"the recorded {c} has {c.KeyCount} frames; expected the plan's {span} (frames {plan.FirstKey}–{plan.LastKey})", nameof(recorded));
                byProperty[c.Property] = c;
            }

            var values = new FilledValues(plan, curves);
            int[]? body = null;
            for (int i = 0; i < curves.Count; i++)
            {
                KeyedCurve curve = curves[i];
                if (!plan.PoseCurveArray[i]) continue;
                int q = IndexOf(HumanoidCurves.RootRotationProperties, curve.Property);
                if (q >= 0)
                {
                    Set(ref body, 4, q, i);
                    continue;
                }

                if (!byProperty.TryGetValue(curve.Property, out ClipCurve? source))
                {
                    throw new KeyFillException(plan.Clip, $"{curve} is keyed but the recording of the filled frames has no such curve", "expected the clip's body and muscle curves only, as HumanTrait names them", nameof(curves));
                }

                values.Scalar(i, f => source.Values[f]);
            }

            if (body != null)
            {
                Complete(plan, body, "", "RootQ.x/y/z/w");
                ClipCurve[] rq = new ClipCurve[4];
                for (int c = 0; c < 4; c++)
                {
                    if (!byProperty.TryGetValue(HumanoidCurves.RootRotationProperties[c], out rq[c]!))
                    {
                        throw new KeyFillException(plan.Clip, "the clip keys the body rotation but the recording has no RootQ curves", "expected a recording of the body and every muscle", nameof(recorded));
                    }
                }

                values.Quaternions(body, f => new QuaternionD(rq[3].Values[f], rq[0].Values[f], rq[1].Values[f], rq[2].Values[f]));
            }

            return values.ToEdit();
        }

        private static int IndexOf(IReadOnlyList<string> list, string value)
        {
            for (int i = 0; i < list.Count; i++)
            {
                if (list[i] == value) return i;
            }

            return -1;
        }

        /// <summary>
        /// The keys a fill adds, curve by curve: every model frame from the first to the last key that the curve has no
        /// key on gets the bake's value there; rotations stay continuous with the clip's own values before them.
        /// </summary>
        private sealed class FilledValues
        {
            private readonly KeyFillPlan _plan;
            private readonly IReadOnlyList<KeyedCurve> _curves;
            private readonly int _span;
            private readonly Dictionary<int, double[]> _added = new Dictionary<int, double[]>();

            public FilledValues(KeyFillPlan plan, IReadOnlyList<KeyedCurve> curves)
            {
                _plan = plan;
                _curves = curves;
                _span = plan.LastKey - plan.FirstKey + 1;
            }

            /// <summary>One curve: the bake's value on every frame it has no key on.</summary>
            public void Scalar(int curve, Func<int, double> baked)
            {
                double?[] own = Own(curve);
                double[] added = Added(curve);
                for (int f = 0; f < _span; f++)
                {
                    if (own[f] == null) added[f] = KeyTime(f) is double t ? Value(_plan, _curves[curve], t) : baked(f);
                }
            }

            /// <summary>Four curves (x, y, z, w) of one rotation: the bake's, each frame in the hemisphere of the frame before.</summary>
            public void Quaternions(int[] curves, Func<int, QuaternionD> baked)
            {
                Group(curves, 4, (f, previous, result) =>
                {
                    QuaternionD q = baked(f);
                    double x = q.X, y = q.Y, z = q.Z, w = q.W;
                    if (x * previous[0] + y * previous[1] + z * previous[2] + w * previous[3] < 0)
                    {
                        x = -x;
                        y = -y;
                        z = -z;
                        w = -w;
                    }

                    result[0] = x;
                    result[1] = y;
                    result[2] = z;
                    result[3] = w;
                });
            }

            /// <summary>Three Euler curves (degrees) of one rotation: the bake's, unwrapped to the frame before.</summary>
            public void Euler(int[] curves, Func<int, QuaternionD> baked) =>
                Group(curves, 3, (f, previous, result) => UnityEuler.Nearest(baked(f), previous, result));

            public KeyFillEdit ToEdit()
            {
                var changes = new List<KeyFillEdit.CurveChange>();
                int filled = 0;
                var keys = new List<CurveKey>();
                var sorted = new List<int>(_added.Keys);
                sorted.Sort();
                foreach (int i in sorted)
                {
                    KeyedCurve before = _curves[i];
                    double[] added = _added[i];
                    keys.Clear();
                    var isNew = new List<bool>();
                    int k = 0;
                    for (int f = 0; f < _span; f++)
                    {
                        if (double.IsNaN(added[f])) continue;
                        float time = (float)((_plan.FirstKey + f) / _plan.FrameRate);
                        while (k < before.Keys.Count && before.Keys[k].Time < time)
                        {
                            keys.Add(before.Keys[k++]);
                            isNew.Add(false);
                        }

                        keys.Add(new CurveKey(time, (float)added[f], 0, 0));
                        isNew.Add(true);
                        filled++;
                    }

                    while (k < before.Keys.Count)
                    {
                        keys.Add(before.Keys[k++]);
                        isNew.Add(false);
                    }

                    // A filled key's slope is its neighbours' (a smooth pass through the baked frames).
                    for (int j = 0; j < keys.Count; j++)
                    {
                        if (!isNew[j]) continue;
                        CurveKey a = keys[j > 0 ? j - 1 : j], b = keys[j + 1 < keys.Count ? j + 1 : j];
                        float slope = b.Time > a.Time ? (b.Value - a.Value) / (b.Time - a.Time) : 0f;
                        keys[j] = new CurveKey(keys[j].Time, keys[j].Value, slope, slope);
                    }

                    changes.Add(new KeyFillEdit.CurveChange(before, new KeyedCurve(before.Path, before.Property, keys)));
                }

                return new KeyFillEdit(_plan.Clip, changes.ToArray(), filled);
            }

            // Rotations: the frame before is the clip's own value on its keys, the filled value elsewhere.
            private void Group(int[] curves, int width, Action<int, double[], double[]> next)
            {
                var own = new double?[width][];
                var added = new double[width][];
                var previous = new double[width];
                var candidate = new double[width];
                for (int c = 0; c < width; c++)
                {
                    own[c] = Own(curves[c]);
                    added[c] = Added(curves[c]);
                    previous[c] = own[c][0] ?? Value(_plan, _curves[curves[c]], KeyTime(0)!.Value);
                    if (own[c][0] == null) added[c][0] = previous[c];
                }

                for (int f = 1; f < _span; f++)
                {
                    next(f, previous, candidate);
                    for (int c = 0; c < width; c++)
                    {
                        if (own[c][f] is double kept)
                        {
                            previous[c] = kept;
                            continue;
                        }

                        // Another curve's key frame: this curve's own value there (the key pose the bake kept), made a key.
                        double value = KeyTime(f) is double t ? Value(_plan, _curves[curves[c]], t) : candidate[c];
                        added[c][f] = value;
                        previous[c] = value;
                    }
                }
            }

            /// <summary>The clip time of the plan's key on span frame <paramref name="f"/>, or null for a frame between keys.</summary>
            private double? KeyTime(int f)
            {
                int at = Array.BinarySearch(_plan.KeyFrameArray, _plan.FirstKey + f);
                return at >= 0 ? _plan.KeyTimeArray[at] : (double?)null;
            }

            /// <summary>The curve's key value on each frame of the span, or null where it has no key.</summary>
            private double?[] Own(int curve)
            {
                var own = new double?[_span];
                foreach (CurveKey key in _curves[curve].Keys)
                {
                    int f = FrameOf(key.Time, _plan.FrameRate) - _plan.FirstKey;
                    if (f >= 0 && f < _span) own[f] = key.Value;
                }

                return own;
            }

            private double[] Added(int curve)
            {
                if (!_added.TryGetValue(curve, out double[]? added))
                {
                    added = new double[_span];
                    for (int f = 0; f < _span; f++) added[f] = double.NaN;
                    _added.Add(curve, added);
                }

                return added;
            }
        }
    }
}
