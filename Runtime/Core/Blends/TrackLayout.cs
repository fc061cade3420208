using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// What a track of clips plays where: each clip alone, and between consecutive clips (by start time) a
    /// <see cref="TrackSpanKind.Blend"/> where they overlap or a <see cref="TrackSpanKind.Gap"/> where time lies between
    /// them (clips that meet exactly cut). The mixer asks <see cref="Locate"/> every frame; it allocates nothing.
    /// </summary>
    /// <remarks>
    /// Timeline blends only two clips at a time; where a clip lies inside another or a third clip reaches into a
    /// blend, that blend is marked with a <see cref="TrackSpan.CrossfadeReason"/> and Timeline's crossfade plays.
    /// </remarks>
    public sealed class TrackLayout
    {
        private readonly TrackClipTiming[] _clips;
        private readonly int[] _order;
        private readonly TrackSpan[] _spans;

        private TrackLayout(TrackClipTiming[] clips, int[] order, TrackSpan[] spans)
        {
            _clips = clips;
            _order = order;
            _spans = spans;
            FirstClip = order.Length > 0 ? order[0] : -1;
            LastClip = FirstClip;
            for (int k = 1; k < order.Length; k++)
            {
                if (clips[order[k]].End >= clips[LastClip].End) LastClip = order[k];
            }
        }

        /// <summary>The clip that starts first (its pre-extrapolation plays before it), −1 with no clips.</summary>
        public int FirstClip { get; }

        /// <summary>The clip that ends last, the later-starting one of a tie (its post-extrapolation plays after it), −1 with no clips.</summary>
        public int LastClip { get; }

        /// <summary>The clips as given.</summary>
        public IReadOnlyList<TrackClipTiming> Clips => _clips;

        /// <summary>Blends and gaps, in track order.</summary>
        public IReadOnlyList<TrackSpan> Spans => _spans;

        /// <summary>Lays out <paramref name="clips"/> (any order; indices in the result are theirs).</summary>
        /// <exception cref="ArgumentException">Two clips start at the same time (<c>clips</c> named).</exception>
        public static TrackLayout Create(IReadOnlyList<TrackClipTiming> clips)
        {
            if (clips == null) throw new ArgumentNullException(nameof(clips));
            var copy = new TrackClipTiming[clips.Count];
            var order = new int[clips.Count];
            for (int i = 0; i < copy.Length; i++)
            {
                copy[i] = clips[i];
                order[i] = i;
            }

            Array.Sort(order, (a, b) => copy[a].Start.CompareTo(copy[b].Start) != 0 ? copy[a].Start.CompareTo(copy[b].Start) : a.CompareTo(b));
            var spans = new List<TrackSpan>();
            for (int k = 0; k + 1 < order.Length; k++)
            {
                int a = order[k], b = order[k + 1];
                TrackClipTiming from = copy[a], to = copy[b];
                if (to.Start == from.Start)
                {
                    throw new ArgumentException($"clips {a} and {b} both start at {from.Start} s; expected clips at different start times, as Timeline places them", nameof(clips));
                }

                if (to.Start > from.End)
                {
                    spans.Add(new TrackSpan(TrackSpanKind.Gap, a, b, from, to, from.End, to.Start, null));
                }
                else if (to.Start < from.End)
                {
                    double end = Math.Min(from.End, to.End);
                    string? reason = null;
                    if (to.End <= from.End) reason = $"clip {b} lies inside clip {a}";
                    else if (k + 2 < order.Length && copy[order[k + 2]].Start < end) reason = $"clip {order[k + 2]} starts inside the blend of clips {a} and {b}";
                    else if (k > 0 && copy[order[k - 1]].End > to.Start) reason = $"clip {order[k - 1]} still plays where clips {a} and {b} blend";
                    spans.Add(new TrackSpan(TrackSpanKind.Blend, a, b, from, to, to.Start, end, reason));
                }
            }

            return new TrackLayout(copy, order, spans.ToArray());
        }

        /// <summary>
        /// What plays at track time <paramref name="time"/>: a span when it lies inside one (its end belongs to the clip after
        /// it; a gap is the model's whatever extrapolation borders it, see <see cref="TrackSpan.ExtrapolationOverridden"/>),
        /// else the clip that covers it, else before the first clip or after the last that clip's extrapolation, else nothing.
        /// </summary>
        public TrackMoment Locate(double time)
        {
            for (int s = 0; s < _spans.Length; s++)
            {
                TrackSpan span = _spans[s];
                if (time >= span.Start && time < span.End) return new TrackMoment(TrackMomentKind.Span, -1, 0, s, (time - span.Start) / span.Duration);
            }

            // The latest-starting clip that covers the time plays (after a cut, the next clip).
            for (int k = _order.Length - 1; k >= 0; k--)
            {
                TrackClipTiming clip = _clips[_order[k]];
                if (time >= clip.Start && time <= clip.End) return new TrackMoment(TrackMomentKind.Clip, _order[k], clip.LocalTime(time), -1, 0);
            }

            // Outside every clip and span: before the first clip (from time 0, Timeline's first pre-extrapolation) and after the
            // clip that ends last, their extrapolation plays as on an Animation Track (Timeline 1.8.10
            // Runtime/Utilities/Extrapolation.cs:28-49, Runtime/TimelineClip.cs:717-731).
            if (FirstClip >= 0)
            {
                TrackClipTiming first = _clips[FirstClip];
                if (time < first.Start)
                {
                    if (time >= 0 && first.PreExtrapolation != TrackExtrapolation.None)
                    {
                        return new TrackMoment(TrackMomentKind.Clip, FirstClip, first.ExtrapolatedTime(time, first.PreExtrapolation), -1, 0, first.PreExtrapolation);
                    }
                }
                else
                {
                    TrackClipTiming clip = _clips[LastClip];
                    if (time > clip.End && clip.PostExtrapolation != TrackExtrapolation.None)
                    {
                        return new TrackMoment(TrackMomentKind.Clip, LastClip, clip.ExtrapolatedTime(time, clip.PostExtrapolation), -1, 0, clip.PostExtrapolation);
                    }
                }
            }

            return new TrackMoment(TrackMomentKind.None, -1, 0, -1, 0);
        }
    }
}
