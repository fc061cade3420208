using System;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// One float curve of a clip, engine-free: which transform (<see cref="Path"/>, relative to the
    /// character's root) and property it animates, and one key per frame with its tangents. The editor
    /// copies it into a <c>UnityEngine.AnimationCurve</c> key for key.
    /// </summary>
    public sealed class ClipCurve
    {
        internal ClipCurve(string path, string property, float[] times, float[] values, float[] inTangents, float[] outTangents)
        {
            Path = path;
            Property = property;
            Times = times;
            Values = values;
            InTangents = inTangents;
            OutTangents = outTangents;
        }

        /// <summary>Transform path relative to the character's root ("" for the root itself), as Unity's curve bindings use.</summary>
        public string Path { get; }

        /// <summary>Transform property, e.g. <c>m_LocalRotation.x</c> or <c>m_LocalPosition.y</c>.</summary>
        public string Property { get; }

        /// <summary>Key times in seconds.</summary>
        public float[] Times { get; }

        /// <summary>Key values (Unity space).</summary>
        public float[] Values { get; }

        /// <summary>Incoming slope of each key (value per second).</summary>
        public float[] InTangents { get; }

        /// <summary>Outgoing slope of each key (value per second).</summary>
        public float[] OutTangents { get; }

        /// <summary>Number of keys.</summary>
        public int KeyCount => Times.Length;

        /// <inheritdoc />
        public override string ToString() => $"{(Path.Length == 0 ? "<root>" : Path)}:{Property} ({KeyCount} keys)";

        internal static void LinearTangents(float[] times, float[] values, float[] inTangents, float[] outTangents)
        {
            // Linear segments between frames: each key's slopes are those of the neighbouring segments, so
            // the clip plays the baked frames exactly and interpolates linearly between them.
            int n = times.Length;
            for (int i = 0; i < n; i++)
            {
                float before = i > 0 ? Slope(times, values, i - 1, i) : (n > 1 ? Slope(times, values, 0, 1) : 0f);
                float after = i + 1 < n ? Slope(times, values, i, i + 1) : before;
                inTangents[i] = i > 0 ? before : after;
                outTangents[i] = after;
            }
        }

        private static float Slope(float[] times, float[] values, int a, int b)
        {
            float dt = times[b] - times[a];
            return dt > 0 ? (values[b] - values[a]) / dt : 0f;
        }

        internal static ClipCurve Create(string path, string property, float[] times, float[] values)
        {
            if (times.Length != values.Length) throw new ArgumentException("one value per key time is needed");
            var inT = new float[times.Length];
            var outT = new float[times.Length];
            LinearTangents(times, values, inT, outT);
            return new ClipCurve(path, property, times, values, inT, outT);
        }
    }
}
