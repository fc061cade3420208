using System;
using DeltaInterpolator.Core.Characters;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// Where one clip puts the character on a track that places its clips (Timeline's <i>Apply Transform Offsets</i>), for
    /// any time its playable is given: the clip's offset, then the clip's root motion from its first frame (Timeline's
    /// <c>AnimationPlayableAsset.removeStartOffset</c>, on by default: "play relative to its first keyframe") or from the
    /// animation's own origin (off), a looping clip adding one cycle's displacement per cycle played, as root motion does.
    /// The root motion is the root bone's ground position and facing (<see cref="RootPlacement.OfPose"/>), sampled once
    /// when the path is made — the same sampling a blend's or gap's root travel reads (<see cref="SpanRootPlan"/>) — and
    /// read between samples linearly. Reading allocates nothing.
    /// </summary>
    /// <remarks>
    /// Timeline 1.8.10 places a clip's root motion this way on an Animation Track in transform-offset mode: the clip's
    /// playable (<c>AnimationClipPlayable</c>, <c>SetRemoveStartOffset</c>) is wrapped in an <c>AnimationOffsetPlayable</c>
    /// at the clip's position and rotation (<c>Runtime/Animation/AnimationPlayableAsset.cs:225-264</c>) and the track's own
    /// offset is put over the mix (<c>AnimationTrack.cs:816-849</c>); the result is absolute
    /// (<c>AnimationMotionXToDeltaPlayable.SetAbsoluteMotion</c>, <c>AnimationTrack.cs:617-627, 739-748</c>).
    /// </remarks>
    public sealed class ClipRootPath
    {
        /// <summary>Root-motion samples per second of animation: twice the model's rate; a walk's hips read between them are off by under 0.1 mm.</summary>
        public const double DefaultSamplesPerSecond = 60;

        // Raw root placements at k · _step seconds of the animation (yaw unwrapped), the last at its length.
        private readonly RootPlacement[] _samples;
        private readonly double _step;
        private readonly double _length;
        private readonly bool _loops;
        // The clip's offset with the first frame's placement taken out (removeStartOffset) or not.
        private readonly RootPlacement _origin;
        // One cycle's displacement in the raw samples' frame: P(length) ∘ P(0)⁻¹.
        private readonly RootPlacement _cycle;

        private ClipRootPath(RootPlacement[] samples, double length, bool loops, RootPlacement offset, RootPlacement origin, RootPlacement cycle)
        {
            _samples = samples;
            _step = samples.Length > 1 ? length / (samples.Length - 1) : 1;
            _length = length;
            _loops = loops;
            Offset = offset;
            _origin = origin;
            _cycle = cycle;
        }

        /// <summary>The clip's offset (its position and yaw in the track's space).</summary>
        public RootPlacement Offset { get; }

        /// <summary>
        /// The path of <paramref name="clip"/> on <paramref name="rig"/>: its root placement sampled at
        /// <paramref name="samplesPerSecond"/> over its animation (<paramref name="animationLength"/> seconds), placed at
        /// <paramref name="offset"/>.
        /// </summary>
        /// <param name="clip">The clip's poses.</param>
        /// <param name="rig">The character.</param>
        /// <param name="animationLength">The animation's length in seconds (<see cref="TrackClipTiming.AnimationLength"/>).</param>
        /// <param name="loops">Whether the animation loops (its root motion then accumulates a cycle per loop).</param>
        /// <param name="offset">The clip's offset (Timeline's <c>AnimationPlayableAsset.position</c>/<c>rotation</c> on the ground).</param>
        /// <param name="removeStartOffset">Whether the root motion counts from the animation's first frame (Timeline's default) or its own origin.</param>
        /// <param name="samplesPerSecond">Samples per second of animation.</param>
        /// <exception cref="ArgumentOutOfRangeException">A length, offset or rate that is not finite and positive (the parameter named), or over a million samples.</exception>
        public static ClipRootPath Sample(IClipPoses clip, CharacterRig rig, double animationLength, bool loops, RootPlacement offset, bool removeStartOffset,
            double samplesPerSecond = DefaultSamplesPerSecond)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (!(animationLength > 0) || double.IsInfinity(animationLength)) throw new ArgumentOutOfRangeException(nameof(animationLength), animationLength, "expected an animation length above 0 seconds");
            if (!(samplesPerSecond > 0) || double.IsInfinity(samplesPerSecond)) throw new ArgumentOutOfRangeException(nameof(samplesPerSecond), samplesPerSecond, "expected a sampling rate above 0 per second");
            RootPlacement.RequireFinite(offset, nameof(offset));
            double count = Math.Ceiling(animationLength * samplesPerSecond);
            if (count > 1e6) throw new ArgumentOutOfRangeException(nameof(samplesPerSecond), samplesPerSecond, $"{count} samples of a {animationLength} s animation; expected at most a million (a lower rate)");
            int intervals = Math.Max(1, (int)count);
            var samples = new RootPlacement[intervals + 1];
            var root = new double[3];
            var rotations = new double[4 * rig.Skeleton.JointCount];
            for (int k = 0; k <= intervals; k++)
            {
                clip.Sample(k == intervals ? animationLength : animationLength * k / intervals, root, rotations);
                RootPlacement at = RootPlacement.OfPose(rig, root, rotations.AsSpan(0, 4));
                // Unwrapped: the facing turns continuously between samples.
                samples[k] = k == 0 ? at : new RootPlacement(at.X, at.Z, samples[k - 1].Yaw + RootPlacement.WrapYaw(at.Yaw - samples[k - 1].Yaw));
            }

            RootPlacement first = samples[0];
            RootPlacement origin = removeStartOffset ? offset.Then(first.Inverse()) : offset;
            return new ClipRootPath(samples, animationLength, loops, offset, origin, samples[intervals].Then(first.Inverse()));
        }

        /// <summary>
        /// A clip that does not move the root (or has no animation): the character stands at <paramref name="offset"/> while it
        /// plays. (Timeline puts no offset on such a clip: pass the identity to stand at the track's offset.)
        /// </summary>
        public static ClipRootPath Still(RootPlacement offset)
        {
            RootPlacement.RequireFinite(offset, nameof(offset));
            return new ClipRootPath(new[] { RootPlacement.Identity }, 1, false, offset, offset, RootPlacement.Identity);
        }

        /// <summary>
        /// Where the clip puts the character when its playable is at <paramref name="playedTime"/> (<see cref="TrackClipTiming.PlayedTime"/>:
        /// not wrapped; held at the animation's ends unless it loops), in the track's space before the track's own offset.
        /// </summary>
        public RootPlacement At(double playedTime)
        {
            double time = playedTime;
            long cycles = 0;
            if (_loops && double.IsFinite(time))
            {
                double turns = Math.Floor(time / _length);
                cycles = (long)Math.Max(-1e15, Math.Min(1e15, turns));
                time -= turns * _length;
            }

            if (!(time > 0)) time = 0;
            if (time > _length) time = _length;
            double f = time / _step;
            int k = Math.Min((int)f, _samples.Length - 2);
            RootPlacement raw;
            if (k < 0)
            {
                raw = _samples[0];
            }
            else
            {
                double t = f - k;
                RootPlacement a = _samples[k], b = _samples[k + 1];
                raw = new RootPlacement(a.X + t * (b.X - a.X), a.Z + t * (b.Z - a.Z), a.Yaw + t * (b.Yaw - a.Yaw));
            }

            return cycles == 0 ? _origin.Then(raw) : _origin.Then(Power(cycles < 0 ? _cycle.Inverse() : _cycle, Math.Abs(cycles))).Then(raw);
        }

        // step ∘ step ∘ … (count times), by squaring: a clip looped for hours costs a few dozen compositions a frame.
        private static RootPlacement Power(RootPlacement step, long count)
        {
            RootPlacement result = RootPlacement.Identity;
            for (; count > 0; count >>= 1)
            {
                if ((count & 1) != 0) result = result.Then(step);
                step = step.Then(step);
            }

            return result;
        }
    }
}
