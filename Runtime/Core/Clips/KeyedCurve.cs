using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// A float curve of a clip as an animator keyed it, engine-free: the binding (transform path relative to the
    /// animated GameObject, property) and its keys in time order, every field of each key (<see cref="CurveKey"/>).
    /// The editor copies Unity's <c>AnimationCurve</c> into it and back key for key; <see cref="KeyFill"/> reads it.
    /// </summary>
    public sealed class KeyedCurve
    {
        private readonly CurveKey[] _keys;

        /// <summary>A curve on <paramref name="path"/>'s <paramref name="property"/> with <paramref name="keys"/> (copied).</summary>
        /// <exception cref="ArgumentException">Keys not in increasing time order.</exception>
        public KeyedCurve(string path, string property, IReadOnlyList<CurveKey> keys)
        {
            Path = path ?? throw new ArgumentNullException(nameof(path));
            Property = property ?? throw new ArgumentNullException(nameof(property));
            if (keys == null) throw new ArgumentNullException(nameof(keys));
            _keys = new CurveKey[keys.Count];
            for (int i = 0; i < _keys.Length; i++)
            {
                _keys[i] = keys[i];
                if (i > 0 && !(keys[i].Time > keys[i - 1].Time))
                {
                    throw new ArgumentException($"{Describe(path, property)}: key {i} at {keys[i].Time} s does not come after key {i - 1} at {keys[i - 1].Time} s; expected keys in increasing time order", nameof(keys));
                }
            }
        }

        /// <summary>Transform path relative to the animated GameObject ("" for the GameObject itself).</summary>
        public string Path { get; }

        /// <summary>The property, e.g. <c>m_LocalRotation.x</c>, <c>localEulerAnglesRaw.y</c>, <c>RootT.z</c>.</summary>
        public string Property { get; }

        /// <summary>The keys in time order.</summary>
        public IReadOnlyList<CurveKey> Keys => _keys;

        /// <summary>True when <paramref name="other"/> has the same binding and the same keys, bit for bit.</summary>
        public bool SameAs(KeyedCurve other)
        {
            if (other == null || other.Path != Path || other.Property != Property || other._keys.Length != _keys.Length) return false;
            for (int i = 0; i < _keys.Length; i++)
            {
                if (!_keys[i].Equals(other._keys[i])) return false;
            }

            return true;
        }

        /// <summary>
        /// The curve's value at <paramref name="time"/> as Unity plays an unweighted curve: Hermite segments between
        /// keys from their tangents (an infinite tangent holds the earlier key's value: a stepped key), the first
        /// and last values held outside the keys.
        /// </summary>
        /// <exception cref="InvalidOperationException">No keys, or a weighted segment around <paramref name="time"/> (a Bézier in time, which this does not evaluate).</exception>
        public double Evaluate(double time)
        {
            if (_keys.Length == 0) throw new InvalidOperationException($"{this} has no keys");
            if (time <= _keys[0].Time) return _keys[0].Value;
            int last = _keys.Length - 1;
            if (time >= _keys[last].Time) return _keys[last].Value;
            int i = 0;
            while (_keys[i + 1].Time <= time) i++;
            CurveKey a = _keys[i], b = _keys[i + 1];
            if (time == a.Time) return a.Value;
            if (a.OutWeighted || b.InWeighted)
            {
                throw new InvalidOperationException($"{this}: the segment {a.Time}–{b.Time} s has weighted tangents; expected unweighted tangents there (or a key on every pose curve at each key frame)");
            }

            if (float.IsInfinity(a.OutTangent) || float.IsInfinity(b.InTangent)) return a.Value;
            double dt = (double)b.Time - a.Time;
            double s = (time - a.Time) / dt;
            double s2 = s * s, s3 = s2 * s;
            double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
            return h00 * a.Value + h10 * dt * a.OutTangent + h01 * b.Value + h11 * dt * b.InTangent;
        }

        /// <inheritdoc />
        public override string ToString() => Describe(Path, Property);

        internal static string Describe(string path, string property) => (path.Length == 0 ? "<root>" : path) + ":" + property;
    }
}
