using System;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// One key of a float curve as Unity's <c>Keyframe</c> holds it, engine-free: time, value, both tangents and
    /// weights, the weighted mode and the editor's packed tangent mode (<c>AnimationUtility</c>'s left and right
    /// <c>TangentMode</c> and the broken flag). Compared field for field, bit for bit: an animator's key is the
    /// same key only when nothing of it changed.
    /// </summary>
    public readonly struct CurveKey : IEquatable<CurveKey>
    {
        /// <summary>A key with every field given.</summary>
        public CurveKey(float time, float value, float inTangent, float outTangent, float inWeight = 0f, float outWeight = 0f, int weightedMode = 0, int tangentMode = 0)
        {
            Time = time;
            Value = value;
            InTangent = inTangent;
            OutTangent = outTangent;
            InWeight = inWeight;
            OutWeight = outWeight;
            WeightedMode = weightedMode;
            TangentMode = tangentMode;
        }

        /// <summary>Time in seconds.</summary>
        public float Time { get; }

        /// <summary>The curve's value at <see cref="Time"/>.</summary>
        public float Value { get; }

        /// <summary>Incoming slope (value per second).</summary>
        public float InTangent { get; }

        /// <summary>Outgoing slope (value per second).</summary>
        public float OutTangent { get; }

        /// <summary>Incoming weight (used when <see cref="WeightedMode"/> has bit 1).</summary>
        public float InWeight { get; }

        /// <summary>Outgoing weight (used when <see cref="WeightedMode"/> has bit 2).</summary>
        public float OutWeight { get; }

        /// <summary>Unity's <c>WeightedMode</c>: 0 none, 1 in, 2 out, 3 both.</summary>
        public int WeightedMode { get; }

        /// <summary>The editor's tangent mode as Unity packs it: bit 0 broken, bits 1–4 the left mode, bits 5–8 the right.</summary>
        public int TangentMode { get; }

        /// <summary>True when the incoming side is weighted (a Bézier in time, not a Hermite segment).</summary>
        public bool InWeighted => (WeightedMode & 1) != 0;

        /// <summary>True when the outgoing side is weighted.</summary>
        public bool OutWeighted => (WeightedMode & 2) != 0;

        /// <inheritdoc />
        public bool Equals(CurveKey other) =>
            Same(Time, other.Time) && Same(Value, other.Value) && Same(InTangent, other.InTangent) && Same(OutTangent, other.OutTangent)
            && Same(InWeight, other.InWeight) && Same(OutWeight, other.OutWeight) && WeightedMode == other.WeightedMode && TangentMode == other.TangentMode;

        /// <inheritdoc />
        public override bool Equals(object? obj) => obj is CurveKey other && Equals(other);

        /// <inheritdoc />
        public override int GetHashCode() => HashCode.Combine(Time, Value, InTangent, OutTangent, TangentMode);

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant($"({Time} s: {Value}, in {InTangent}, out {OutTangent}, mode {TangentMode})");

        // Bit for bit: NaN equals the same NaN, and −0 is not +0 (an edit that restores a key restores its bits).
        private static bool Same(float a, float b) => BitConverter.SingleToInt32Bits(a) == BitConverter.SingleToInt32Bits(b);
    }
}
