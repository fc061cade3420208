using System;
using DeltaInterpolator.Core.Characters;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// A blend's or gap's frames and its root travel together, as a track with root motion plays them
    /// (<see cref="SpanRootTravel"/>): the first clip's history and key as sampled (in the first clip's frame where the span
    /// starts), the second clip's target key placed where the character stands when the span ends, then the span baked once
    /// through the <see cref="BlendCache"/> and the model's root trajectory read off its frames. Without root motion it is
    /// the cache's span, unchanged, and no travel.
    /// </summary>
    /// <remarks>
    /// <para>Where the span ends the character (scene offsets: each clip's root motion from where the character stands) —
    /// a <b>gap</b>: where the first clip's last step, kept up for every model frame of the gap, brings it; a
    /// <b>blend</b>: where Timeline's mix of both clips' root motion over the blend brings it, each model frame's step the
    /// first clip's step weighted by its mix-out and the second clip's by its mix-in (Timeline 1.8.10: a clip's weight is
    /// <c>EvaluateMixIn(t) * EvaluateMixOut(t)</c>, <c>Runtime/Evaluation/RuntimeClip.cs:92-101</c>; over a blend the
    /// mix-in is the blend-in curve at the fraction of the overlap and the mix-out the blend-out curve,
    /// <c>Runtime/TimelineClip.cs:558-599</c>, by default <c>AnimationCurve.EaseInOut(0, 0, 1, 1)</c> and its mirror — two
    /// keys with flat tangents, 3u² − 2u³ (UnityCsReference <c>Runtime/Export/Animation/AnimationCurve.bindings.cs:254-264</c>) —
    /// and a Manual curve on one side gets the other side's made to sum to 1 with it,
    /// <c>Runtime/Utilities/BlendUtility.cs:50-77</c>, <c>Runtime/CurveEditUtility.cs:8-22</c>). So after a blend the
    /// character stands where Timeline's crossfade would have left it, and the model's in-between gets it there.</para>
    /// <para>With transform offsets (a track that places its clips): the second clip's placement, given relative to where
    /// the first clip's root motion has the character where the span starts, and the model's trajectory bent to land there
    /// with the clips' own steps at both ends (<see cref="SpanRootTravel.Land"/>).</para>
    /// </remarks>
    public static class SpanRootPlan
    {
        /// <summary>The frames and root travel of the blend or gap <paramref name="span"/>.</summary>
        /// <param name="cache">Where the span is baked once.</param>
        /// <param name="model">The model and map.</param>
        /// <param name="rig">The character.</param>
        /// <param name="span">A blend or gap of the track's layout.</param>
        /// <param name="from">The clip the span leaves.</param>
        /// <param name="to">The clip the span arrives in.</param>
        /// <param name="mode">How the clips carry root motion and are placed.</param>
        /// <param name="arrival">With transform offsets: the second clip's placement where the span ends, relative to where the first clip's root motion has the character where the span starts (Timeline: its clip offset against the first one's, root travel included); else unused.</param>
        /// <param name="frames">The span's frames (with root motion: the model's in-between to the placed target; a blend Timeline crossfades has none, and no travel).</param>
        /// <param name="warn">Told once, when the span is computed, that the model's in-between is not what plays.</param>
        /// <param name="blendIn">A blend's mix-in: the second clip's weight at a fraction (0 to 1) of the blend, the first clip's being 1 minus it; null: Timeline's default ease, 3u² − 2u³. Unused for a gap.</param>
        /// <exception cref="ArgumentException">The span has no length (<c>span</c> named).</exception>
        public static SpanRootTravel Bake(BlendCache cache, BlendModel model, CharacterRig rig, TrackSpan span, IClipPoses from, IClipPoses to, RootTravelMode mode,
            RootPlacement arrival, out BlendFrames frames, Action<string>? warn = null, Func<double, double>? blendIn = null)
        {
            if (cache == null) throw new ArgumentNullException(nameof(cache));
            if (model == null) throw new ArgumentNullException(nameof(model));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (from == null) throw new ArgumentNullException(nameof(from));
            if (to == null) throw new ArgumentNullException(nameof(to));
            if (!(span.Duration > 0)) throw new ArgumentException($"a span of {span.Duration} s; expected a blend or gap of a track layout", nameof(span));
            if (mode < RootTravelMode.None || mode > RootTravelMode.TransformOffset) throw new ArgumentOutOfRangeException(nameof(mode), mode, "expected None, SceneOffset or TransformOffset");
            if (mode == RootTravelMode.None)
            {
                frames = cache.Get(model, rig, span, from, to, warn);
                return SpanRootTravel.None(Math.Max(2, frames.FrameCount));
            }

            double frameTime = 1.0 / model.Contract.FramesPerSecond;
            int bones = rig.Skeleton.JointCount;
            var root = new double[3];
            var rotations = new double[4 * bones];
            RootPlacement Placement(IClipPoses clip, double time)
            {
                clip.Sample(time, root, rotations);
                return RootPlacement.OfPose(rig, root, rotations.AsSpan(0, 4));
            }

            // The clips' own steps at the span's ends, one model frame each, read where the track plays them.
            RootPlacement leaving = Placement(from, span.FromTime);
            RootPlacement lastStep = Placement(from, span.FromClip.LocalTime(span.Start - frameTime)).StepTo(leaving);
            RootPlacement starting = Placement(to, span.ToTime);
            RootPlacement firstStep = starting.StepTo(Placement(to, span.ToClip.LocalTime(span.End + frameTime)));
            int steps = Math.Max(1, model.MissingFrames(span.Duration) + 1);
            RootPlacement target;
            if (mode == RootTravelMode.TransformOffset)
            {
                target = leaving.Then(arrival);
            }
            else if (span.Kind == TrackSpanKind.Gap)
            {
                // Scene offsets in a gap: where the first clip's last step, kept up for every model frame of the gap, brings the character.
                target = leaving;
                for (int k = 0; k < steps; k++) target = target.Then(lastStep);
            }
            else
            {
                // Scene offsets in a blend: Timeline's mix of both clips' root motion, one model frame at a time, each clip's
                // step read where the track plays it and weighted at the frame's middle.
                target = leaving;
                double h = span.Duration / steps;
                for (int k = 0; k < steps; k++)
                {
                    double t0 = span.Start + k * h, t1 = k == steps - 1 ? span.End : t0 + h;
                    RootPlacement a = Placement(from, span.FromClip.LocalTime(t0)).StepTo(Placement(from, span.FromClip.LocalTime(t1)));
                    RootPlacement b = Placement(to, span.ToClip.LocalTime(t0)).StepTo(Placement(to, span.ToClip.LocalTime(t1)));
                    double u = (k + 0.5) / steps;
                    double w = blendIn != null ? blendIn(u) : u * u * (3 - 2 * u);
                    if (!(w >= 0 && w <= 1)) throw new ArgumentOutOfRangeException(nameof(blendIn), w, $"a mix-in weight at {u:0.###} of the blend; expected 0 to 1");
                    target = target.Then(new RootPlacement((1 - w) * a.X + w * b.X, (1 - w) * a.Z + w * b.Z,
                        (1 - w) * RootPlacement.WrapYaw(a.Yaw) + w * RootPlacement.WrapYaw(b.Yaw)));
                }
            }

            var placed = new PlacedClipPoses(to, rig, target.Then(starting.Inverse()));
            frames = cache.Get(model, rig, span, from, placed, warn);
            // Timeline's crossfade plays (a blend the model cannot fill): no frames, and the clips' own root motion.
            if (frames.Motion == null) return SpanRootTravel.None(2);
            RootPlacement[] trajectory = SpanRootTravel.Trajectory(rig, frames);
            return mode == RootTravelMode.SceneOffset ? SpanRootTravel.Follow(trajectory) : SpanRootTravel.Land(trajectory, target, lastStep, firstStep);
        }
    }
}
