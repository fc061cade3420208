using System;
using DeltaInterpolator.Core.Characters;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// A gap's frames and its root travel together, as a track with root motion plays them (<see cref="GapRootTravel"/>):
    /// the first clip's keys as sampled, the second clip's target key placed where its root motion starts the character —
    /// with scene offsets where the first clip's last step, kept up over the gap, brings it; with transform offsets at
    /// the second clip's own placement — then the gap baked once through the <see cref="BlendCache"/> and the model's
    /// root trajectory read off its frames. Without root motion it is the cache's gap, unchanged, and no travel.
    /// </summary>
    public static class GapRootPlan
    {
        /// <summary>The frames and root travel of the gap <paramref name="span"/>.</summary>
        /// <param name="cache">Where the gap is baked once.</param>
        /// <param name="model">The model and map.</param>
        /// <param name="rig">The character.</param>
        /// <param name="span">A gap of the track's layout.</param>
        /// <param name="from">The clip the gap leaves.</param>
        /// <param name="to">The clip the gap arrives in.</param>
        /// <param name="mode">How the clips carry root motion and are placed.</param>
        /// <param name="arrival">With transform offsets: the second clip's placement relative to where the first clip's root motion leaves the character (Timeline: its clip offset against the first one's, root travel included); else unused.</param>
        /// <param name="frames">The gap's frames (with root motion: the model's in-between to the placed target).</param>
        /// <param name="warn">Told once, when the gap is computed, that the model's in-between is not what plays.</param>
        /// <exception cref="ArgumentException">The span is no gap (<c>span</c> named).</exception>
        public static GapRootTravel Bake(BlendCache cache, BlendModel model, CharacterRig rig, TrackSpan span, IClipPoses from, IClipPoses to, RootTravelMode mode,
            RootPlacement arrival, out BlendFrames frames, Action<string>? warn = null)
        {
            if (cache == null) throw new ArgumentNullException(nameof(cache));
            if (model == null) throw new ArgumentNullException(nameof(model));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (from == null) throw new ArgumentNullException(nameof(from));
            if (to == null) throw new ArgumentNullException(nameof(to));
            if (span.Kind != TrackSpanKind.Gap) throw new ArgumentException($"a {span.Kind} from {span.Start} s to {span.End} s; expected a gap (a blend's root motion is Timeline's mix of its clips)", nameof(span));
            if (mode < RootTravelMode.None || mode > RootTravelMode.TransformOffset) throw new ArgumentOutOfRangeException(nameof(mode), mode, "expected None, SceneOffset or TransformOffset");
            if (mode == RootTravelMode.None)
            {
                frames = cache.Get(model, rig, span, from, to, warn);
                return GapRootTravel.None(Math.Max(2, frames.FrameCount));
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

            // The clips' own steps at the gap's ends, one model frame each, read where the track plays them.
            RootPlacement leaving = Placement(from, span.FromTime);
            RootPlacement lastStep = Placement(from, span.FromClip.LocalTime(span.Start - frameTime)).StepTo(leaving);
            RootPlacement starting = Placement(to, span.ToTime);
            RootPlacement firstStep = starting.StepTo(Placement(to, span.ToClip.LocalTime(span.End + frameTime)));
            RootPlacement target;
            if (mode == RootTravelMode.TransformOffset)
            {
                target = leaving.Then(arrival);
            }
            else
            {
                // Scene offsets: where the first clip's last step, kept up for every model frame of the gap, brings the character.
                int steps = Math.Max(1, model.MissingFrames(span.Duration) + 1);
                target = leaving;
                for (int k = 0; k < steps; k++) target = target.Then(lastStep);
            }

            var placed = new PlacedClipPoses(to, rig, target.Then(starting.Inverse()));
            frames = cache.Get(model, rig, span, from, placed, warn);
            RootPlacement[] trajectory = GapRootTravel.Trajectory(rig, frames);
            return mode == RootTravelMode.SceneOffset ? GapRootTravel.Follow(trajectory) : GapRootTravel.Land(trajectory, target, lastStep, firstStep);
        }
    }
}
