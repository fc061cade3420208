using System;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// The part of a clip a fill may touch, in seconds of the clip (both ends included): only the gaps between
    /// the keys inside it are filled. The Animation window's key selection is not public API, so the fill's
    /// window asks for this range instead.
    /// </summary>
    public readonly struct FillRange
    {
        /// <summary>The range <paramref name="start"/>..<paramref name="end"/> seconds.</summary>
        public FillRange(double start, double end)
        {
            Start = start;
            End = end;
        }

        /// <summary>First time of the range (seconds).</summary>
        public double Start { get; }

        /// <summary>Last time of the range (seconds).</summary>
        public double End { get; }

        /// <summary>The range in frames of <paramref name="frameRate"/>, e.g. "frames 10–40 (0.333–1.333 s)".</summary>
        public string Describe(double frameRate) =>
            FormattableString.Invariant($"frames {Start * frameRate:0.##}–{End * frameRate:0.##} ({Start:0.###}–{End:0.###} s)");
    }
}
