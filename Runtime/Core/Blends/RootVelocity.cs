using System;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// The root velocity that moves a character from one placement to another in one frame, as an engine applies root
    /// motion: a velocity in the character's own frame (its facing at the frame's start; Unity's
    /// <c>AnimationStream.velocity</c>, see <c>unity-verification.md</c>) and a turn rate about +Y, applied over the frame's
    /// delta time — the character at <c>current.Then(new RootPlacement(x·dt, z·dt, yawRate·dt))</c>. A blend's or gap's
    /// travel (<see cref="SpanRootTravel.Velocity"/>) and a transform-offset track's placement (<see cref="TrackRootPath"/>)
    /// are both handed to the engine by it. Allocation-free.
    /// </summary>
    public static class RootVelocity
    {
        /// <summary>
        /// The velocity (<paramref name="x"/>, <paramref name="z"/>: units per second in <paramref name="current"/>'s frame) and
        /// turn rate (<paramref name="yawRate"/>, radians per second, the shorter way round) that put a character standing at
        /// <paramref name="current"/> exactly on <paramref name="target"/> after <paramref name="seconds"/>. A frame of no
        /// length (0, or not a number: a paused evaluation) cannot move it: all three are 0.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">A placement that is not finite (<c>current</c> or <c>target</c> named).</exception>
        public static void Toward(RootPlacement current, RootPlacement target, double seconds, out double x, out double z, out double yawRate)
        {
            RootPlacement.RequireFinite(current, nameof(current));
            RootPlacement.RequireFinite(target, nameof(target));
            if (!(seconds > 0) || double.IsInfinity(seconds))
            {
                x = z = yawRate = 0;
                return;
            }

            RootPlacement step = current.StepTo(target);
            double turn = step.Yaw;
            // Facings are angles: a target a whole turn (or more) away is the same facing, reached the shorter way.
            if (turn > Math.PI || turn < -Math.PI) turn = RootPlacement.WrapYaw(turn);
            x = step.X / seconds;
            z = step.Z / seconds;
            yawRate = turn / seconds;
        }
    }
}
