using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// Where a blend's or gap's root stands at each model frame, so that the span carries root motion as the track's clips
    /// have it: from where the first clip's root motion has the character where the span starts to where the character
    /// stands when it ends (<see cref="SpanRootPlan"/>), along the model's root trajectory between the span's two keys
    /// (<see cref="RootTravelMode"/>). Placements are in the frame the span's key poses were sampled in (the first clip's);
    /// what an engine applies is the step between two of them (<see cref="Velocity"/>), and the pose shown over a
    /// travelling root is the model's pose with that travel taken out of its root bone (<see cref="InPlace"/>), so that
    /// the character's hips stay where the model put them.
    /// </summary>
    /// <remarks>
    /// <para>Scene offsets: the travel is the model's trajectory itself (<see cref="Follow"/>). Transform offsets: the
    /// model's trajectory plus a cubic correction in (x, z, yaw) that is 0 at the span's first frame and makes the second
    /// frame's step the first clip's last step, the last frame the second clip's placement and the last step the second
    /// clip's first step (<see cref="Land"/>) — a correction, not a rescale: a rescale would scale the first step too,
    /// and the character would jump in speed where the span begins.</para>
    /// <para>Reading (<see cref="At"/>, <see cref="Velocity"/>, <see cref="InPlace"/>) allocates nothing.</para>
    /// </remarks>
    public sealed class SpanRootTravel
    {
        private readonly RootPlacement[] _frames;

        private SpanRootTravel(RootTravelMode mode, RootPlacement[] frames)
        {
            Mode = mode;
            _frames = frames;
        }

        /// <summary>How this span travels.</summary>
        public RootTravelMode Mode { get; }

        /// <summary>Model frames from the span's first pose to its last, both included.</summary>
        public int FrameCount => _frames.Length;

        /// <summary>No travel: the clips' hips carry it (today's behaviour for clips without root motion).</summary>
        public static SpanRootTravel None(int frameCount)
        {
            if (frameCount < 2) throw new ArgumentOutOfRangeException(nameof(frameCount), frameCount, "expected a span of at least 2 model frames (its two keys)");
            return new SpanRootTravel(RootTravelMode.None, new RootPlacement[frameCount]);
        }

        /// <summary>Scene offsets: the model's root trajectory itself, one placement per model frame.</summary>
        public static SpanRootTravel Follow(ReadOnlySpan<RootPlacement> trajectory)
        {
            if (trajectory.Length < 2) throw new ArgumentException($"a trajectory of {trajectory.Length} frame(s); expected a span's frames, its two keys included", nameof(trajectory));
            return new SpanRootTravel(RootTravelMode.SceneOffset, Unwrapped(trajectory));
        }

        /// <summary>
        /// Transform offsets: the model's root trajectory bent so that it starts where it starts (the first clip's last
        /// frame), lands on <paramref name="arrival"/>, and its first and last steps are the clips' own.
        /// </summary>
        /// <param name="trajectory">The model's root placements, one per model frame, the first at the first clip's last frame.</param>
        /// <param name="arrival">Where the second clip starts the character (its placement), in the trajectory's frame.</param>
        /// <param name="lastStep">The first clip's step over its last model frame (in the frame of the placement it starts from).</param>
        /// <param name="firstStep">The second clip's step over its first model frame.</param>
        /// <remarks>A span of fewer than 4 model frames has no room for both steps: its correction is linear (it lands, without the steps).</remarks>
        public static SpanRootTravel Land(ReadOnlySpan<RootPlacement> trajectory, RootPlacement arrival, RootPlacement lastStep, RootPlacement firstStep)
        {
            if (trajectory.Length < 2) throw new ArgumentException($"a trajectory of {trajectory.Length} frame(s); expected a span's frames, its two keys included", nameof(trajectory));
            RootPlacement[] frames = Unwrapped(trajectory);
            int last = frames.Length - 1;
            RootPlacement end = frames[last];
            arrival = new RootPlacement(arrival.X, arrival.Z, end.Yaw + RootPlacement.WrapYaw(arrival.Yaw - end.Yaw));
            // What the correction must add at the second frame, the last and the one before it.
            RootPlacement second = frames[0].Then(lastStep), beforeLast = arrival.Then(firstStep.Inverse());
            double h = 1.0 / last;
            var atSecond = (second.X - frames[1].X, second.Z - frames[1].Z, second.Yaw - frames[1].Yaw);
            var atEnd = (arrival.X - end.X, arrival.Z - end.Z, arrival.Yaw - end.Yaw);
            var atBeforeLast = (beforeLast.X - frames[last - 1].X, beforeLast.Z - frames[last - 1].Z, beforeLast.Yaw - frames[last - 1].Yaw);
            for (int k = 0; k <= last; k++)
            {
                double s = k * h;
                double x, z, yaw;
                if (last < 3)
                {
                    (x, z, yaw) = (s * atEnd.Item1, s * atEnd.Item2, s * atEnd.Item3);
                }
                else
                {
                    x = Cubic(h, atSecond.Item1, atEnd.Item1, atBeforeLast.Item1, s);
                    z = Cubic(h, atSecond.Item2, atEnd.Item2, atBeforeLast.Item2, s);
                    yaw = Cubic(h, atSecond.Item3, atEnd.Item3, atBeforeLast.Item3, s);
                }

                frames[k] = new RootPlacement(frames[k].X + x, frames[k].Z + z, frames[k].Yaw + yaw);
            }

            frames[last] = arrival;
            return new SpanRootTravel(RootTravelMode.TransformOffset, frames);
        }

        /// <summary>The root placements of a span's frames (<see cref="BlendFrames.Motion"/> on <paramref name="rig"/>), yaw unwrapped from frame to frame.</summary>
        public static RootPlacement[] Trajectory(CharacterRig rig, BlendFrames frames)
        {
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (frames?.Motion == null) throw new ArgumentException("a crossfade has no frames; expected a span's frames (model or SLERP)", nameof(frames));
            var result = new RootPlacement[frames.Motion.FrameCount];
            var root = new double[3];
            var rotations = new double[4 * rig.Skeleton.JointCount];
            for (int k = 0; k < result.Length; k++)
            {
                CharacterPoseTrack.ReadUnityPose(rig, frames.Motion, k, root, rotations);
                result[k] = RootPlacement.OfPose(rig, root, rotations.AsSpan(0, 4));
            }

            return Unwrapped(result);
        }

        /// <summary>The placement at model frame <paramref name="frame"/>.</summary>
        public RootPlacement Frame(int frame) => _frames[frame];

        /// <summary>The placement at <paramref name="fraction"/> of the span (0: its start, 1: its end; clamped), linear between model frames as the poses are read.</summary>
        public RootPlacement At(double fraction)
        {
            Segment(fraction, out int k, out double t);
            RootPlacement a = _frames[k], b = _frames[k + 1];
            return new RootPlacement(a.X + t * (b.X - a.X), a.Z + t * (b.Z - a.Z), a.Yaw + t * (b.Yaw - a.Yaw));
        }

        /// <summary>
        /// The root's velocity at <paramref name="fraction"/> of a span of <paramref name="seconds"/>: the step of the model
        /// frame it lies in, per second, in the root's own frame there (what an engine's root motion takes; Unity's
        /// <c>AnimationStream.velocity</c> is in the character's frame, see <c>unity-verification.md</c>), and its turn rate in radians per second.
        /// </summary>
        public void Velocity(double fraction, double seconds, out double x, out double z, out double yawRate)
        {
            Segment(fraction, out int k, out _);
            double frameSeconds = seconds / (_frames.Length - 1);
            RootPlacement here = At(fraction), a = _frames[k], b = _frames[k + 1];
            RootVelocity.Toward(here, new RootPlacement(here.X + b.X - a.X, here.Z + b.Z - a.Z, here.Yaw + b.Yaw - a.Yaw), frameSeconds, out x, out z, out yawRate);
        }

        /// <summary>
        /// Takes the travel at <paramref name="fraction"/> out of a span pose's root bone: the pose as it stands over the root
        /// placed there, so that root and pose together show the model's pose where the model put it. No travel: unchanged.
        /// </summary>
        public void InPlace(CharacterRig rig, double fraction, Span<double> rootPosition, Span<double> rootRotation)
        {
            if (Mode == RootTravelMode.None) return;
            At(fraction).Inverse().Move(rig, rootPosition, rootRotation);
        }

        private void Segment(double fraction, out int k, out double t)
        {
            if (!(fraction > 0)) fraction = 0;
            if (fraction > 1) fraction = 1;
            double f = fraction * (_frames.Length - 1);
            k = Math.Min((int)Math.Floor(f), _frames.Length - 2);
            t = f - k;
        }

        /// <summary>c(s) = a s + b s² + d s³ with c(h) = c1, c(1) = e, c(1 − h) = cn (so c(0) = 0): d = e − a − b, then Cramer's rule.</summary>
        private static double Cubic(double h, double c1, double e, double cn, double s)
        {
            double u = 1 - h;
            double p11 = h - h * h * h, p12 = h * h - h * h * h, r1 = c1 - e * h * h * h;
            double p21 = u - u * u * u, p22 = u * u - u * u * u, r2 = cn - e * u * u * u;
            double det = p11 * p22 - p12 * p21;
            double a = (r1 * p22 - p12 * r2) / det;
            double b = (p11 * r2 - r1 * p21) / det;
            double d = e - a - b;
            return s * (a + s * (b + s * d));
        }

        private static RootPlacement[] Unwrapped(ReadOnlySpan<RootPlacement> trajectory)
        {
            var frames = trajectory.ToArray();
            for (int k = 1; k < frames.Length; k++)
            {
                frames[k] = new RootPlacement(frames[k].X, frames[k].Z, frames[k - 1].Yaw + RootPlacement.WrapYaw(frames[k].Yaw - frames[k - 1].Yaw));
            }

            return frames;
        }
    }
}
