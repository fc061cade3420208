using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// Where the character stands at any time on a track that places its clips (Timeline's <i>Apply Transform Offsets</i>,
    /// an Animation Track's default), in the track's space (the character's parent's): a pure function of the time, as
    /// Timeline's absolute root motion makes it, so that whatever happened before — scrubbing backwards, a jump, the first
    /// frame — the character can be put where Timeline would have it (<see cref="RootVelocity"/>).
    /// </summary>
    /// <remarks>
    /// <list type="bullet">
    /// <item>Inside a clip: the track's offset, then the clip's (<see cref="ClipRootPath"/>: its offset and its root motion at
    /// the time its playable is given, <see cref="TrackClipTiming.PlayedTime"/>).</item>
    /// <item>Inside a blend or gap with root travel: the span's travel (<see cref="SpanRootTravel.Land"/>, transform offsets)
    /// from the first clip's placement where the span starts to the second clip's where it ends — the travel's placements,
    /// in the first clip's sampled frame, carried into the track's space so that its last frame is exactly the second clip's
    /// placement (its first is the first clip's within the model's reconstruction of its key, 1e-5).</item>
    /// <item>A blend without travel (Timeline crossfades it): both clips' placements mixed by the second clip's mix-in, as
    /// Timeline mixes their absolute root motion. A gap without travel: what Timeline plays there (the first clip's
    /// post-extrapolation, else the second clip's pre-extrapolation), else the first clip held at its end.</item>
    /// <item>Before the first clip and after the last: the clip by its extrapolation (<see cref="TrackLayout.Locate"/>);
    /// with none, held at that clip's edge.</item>
    /// </list>
    /// Made when the track's graph is built (<see cref="Travel"/> once per span after its bake); <see cref="At(double)"/> allocates nothing.
    /// </remarks>
    public sealed class TrackRootPath
    {
        private readonly TrackLayout _layout;
        private readonly RootPlacement _track;
        private readonly ClipRootPath[] _clips;
        private readonly SpanRootTravel?[] _travel;
        // Per span: the travel's sampled frame carried into the track's space.
        private readonly RootPlacement[] _travelFrame;
        private readonly Func<double, double>?[] _blendIn;

        /// <summary>The path of the clips of <paramref name="layout"/> (one <see cref="ClipRootPath"/> each, in its order) under the track's offset <paramref name="trackOffset"/>.</summary>
        /// <exception cref="ArgumentException">Not one clip path per clip of the layout (<c>clips</c> named).</exception>
        /// <exception cref="ArgumentOutOfRangeException">A track offset that is not finite.</exception>
        public TrackRootPath(TrackLayout layout, RootPlacement trackOffset, IReadOnlyList<ClipRootPath> clips)
        {
            _layout = layout ?? throw new ArgumentNullException(nameof(layout));
            if (clips == null) throw new ArgumentNullException(nameof(clips));
            if (clips.Count != layout.Clips.Count) throw new ArgumentException($"{clips.Count} clip paths for {layout.Clips.Count} clips; expected one per clip of the layout", nameof(clips));
            RootPlacement.RequireFinite(trackOffset, nameof(trackOffset));

            _track = trackOffset;
            _clips = new ClipRootPath[clips.Count];
            for (int i = 0; i < _clips.Length; i++)
            {
                _clips[i] = clips[i] ?? throw new ArgumentException($"clip path {i} is null; expected one for every clip (ClipRootPath.Still for a clip that does not move the root)", nameof(clips));
            }

            _travel = new SpanRootTravel?[layout.Spans.Count];
            _travelFrame = new RootPlacement[layout.Spans.Count];
            _blendIn = new Func<double, double>?[layout.Spans.Count];
        }

        /// <summary>Where clip <paramref name="clip"/> puts the character when its playable is at <paramref name="playedTime"/> (track offset included).</summary>
        public RootPlacement Clip(int clip, double playedTime) => _track.Then(_clips[clip].At(playedTime));

        /// <summary>
        /// Where span <paramref name="span"/>'s second clip puts the character where the span ends, relative to where the first
        /// clip has it where the span starts: what <see cref="SpanRootPlan.Bake"/> takes as the arrival with transform offsets.
        /// </summary>
        public RootPlacement Arrival(int span)
        {
            TrackSpan s = _layout.Spans[span];
            return Leaving(s).StepTo(Arriving(s));
        }

        /// <summary>
        /// The root travel baked for span <paramref name="span"/> (<see cref="SpanRootPlan.Bake"/> with <see cref="Arrival"/>);
        /// one without travel (Timeline's crossfade) mixes the clips by <paramref name="blendIn"/> (the second clip's weight at a
        /// fraction of a blend; null: Timeline's default ease, 3u² − 2u³).
        /// </summary>
        public void Travel(int span, SpanRootTravel travel, Func<double, double>? blendIn = null)
        {
            if (span < 0 || span >= _travel.Length) throw new ArgumentOutOfRangeException(nameof(span), span, $"expected a span of the layout, 0 to {_travel.Length - 1}");
            _travel[span] = travel ?? throw new ArgumentNullException(nameof(travel));
            _blendIn[span] = blendIn;
            if (travel.Mode == RootTravelMode.TransformOffset)
            {
                _travelFrame[span] = Arriving(_layout.Spans[span]).Then(travel.Frame(travel.FrameCount - 1).Inverse());
            }
        }

        /// <summary>Where the character stands at track time <paramref name="time"/>, in the track's space.</summary>
        /// <exception cref="ArgumentOutOfRangeException">A time that is not a number.</exception>
        public RootPlacement At(double time)
        {
            if (double.IsNaN(time)) throw new ArgumentOutOfRangeException(nameof(time), time, "expected a track time");
            return At(_layout.Locate(time), time);
        }

        /// <summary>
        /// Where the character stands at track time <paramref name="time"/>, which the layout the path was made on has
        /// already located (<paramref name="moment"/>, <see cref="TrackLayout.Locate"/>): for a caller that locates the
        /// playhead once a frame for the pose as well.
        /// </summary>
        public RootPlacement At(TrackMoment moment, double time)
        {
            switch (moment.Kind)
            {
                case TrackMomentKind.Clip:
                    return Clip(moment.Clip, _layout.Clips[moment.Clip].PlayedTime(time, moment.Extrapolation));
                case TrackMomentKind.Span:
                    return InSpan(moment.Span, moment.Fraction, time);
                default:
                    int firstClip = _layout.FirstClip, lastClip = _layout.LastClip;
                    if (firstClip < 0) return _track;
                    TrackClipTiming first = _layout.Clips[firstClip], last = _layout.Clips[lastClip];
                    return time < first.Start ? Clip(firstClip, first.PlayedTime(first.Start, TrackExtrapolation.None)) : Clip(lastClip, last.PlayedTime(last.End, TrackExtrapolation.None));
            }
        }

        private RootPlacement InSpan(int span, double fraction, double time)
        {
            TrackSpan s = _layout.Spans[span];
            SpanRootTravel? travel = _travel[span];
            if (travel != null && travel.Mode == RootTravelMode.TransformOffset) return _travelFrame[span].Then(travel.At(fraction));
            if (s.Kind == TrackSpanKind.Blend)
            {
                // Timeline's crossfade: both clips play, their absolute placements mixed by the blend's weights.
                RootPlacement a = Clip(s.From, s.FromClip.PlayedTime(time, TrackExtrapolation.None)), b = Clip(s.To, s.ToClip.PlayedTime(time, TrackExtrapolation.None));
                Func<double, double>? blendIn = _blendIn[span];
                double w = blendIn != null ? blendIn(fraction) : fraction * fraction * (3 - 2 * fraction);
                return new RootPlacement(a.X + w * (b.X - a.X), a.Z + w * (b.Z - a.Z), a.Yaw + w * RootPlacement.WrapYaw(b.Yaw - a.Yaw));
            }

            if (s.FromClip.PostExtrapolation != TrackExtrapolation.None) return Clip(s.From, s.FromClip.PlayedTime(time, s.FromClip.PostExtrapolation));
            if (s.ToClip.PreExtrapolation != TrackExtrapolation.None) return Clip(s.To, s.ToClip.PlayedTime(time, s.ToClip.PreExtrapolation));
            return Leaving(s);
        }

        // The first clip's placement where the span starts, and the second one's where it ends (inside each clip: no extrapolation).
        private RootPlacement Leaving(TrackSpan s) => Clip(s.From, s.FromClip.PlayedTime(s.Start, TrackExtrapolation.None));

        private RootPlacement Arriving(TrackSpan s) => Clip(s.To, s.ToClip.PlayedTime(s.End, TrackExtrapolation.None));
    }
}
