using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Blends;

namespace DeltaInterpolator.Tests.Blends
{
    /// <summary>
    /// The transform-offset case of <c>NeuralTrackRootMotionVerification</c> (Tests/PlayMode/Timeline) and what its recording
    /// must show. One Neural Animation Track set to Apply Transform Offsets, with a track offset, plays Walk 0–<see cref="FirstEnd"/>
    /// at one clip offset, a gap, and Walk again from <see cref="SecondStart"/> to <see cref="SecondEnd"/> at another, on a
    /// character that starts somewhere else; while it plays, the playhead jumps from <see cref="JumpAt"/> back to
    /// <see cref="JumpBackTo"/>. The checks: (e) <see cref="StartsAtTheOffset"/> — where each Walk starts the character
    /// stands at the track's offset ∘ the clip's, whatever it did before; (f) <see cref="StandsWhereItStoodAtTheSameTime"/> —
    /// after the jump it stands where it stood at the same times before (Timeline's absolute placement: a function of the
    /// time). Engine-free, so that <see cref="TransformOffsetChecksTests"/> shows here that each fails on the fault it is for.
    /// </summary>
    public static class TransformOffsetChecks
    {
        // The track, in seconds (the Demo's Walk cut, one 1.1 s gait cycle).
        public const double FirstEnd = 1.1;
        public const double SecondStart = 1.7; // a 0.6 s gap
        public const double SecondEnd = 2.8;
        public const double JumpAt = 2.2;      // while the second Walk plays, the playhead is set back…
        public const double JumpBackTo = 0.4;  // …into the first Walk

        // The offsets (in the character's parent's space; the figure has none): the track's, then each Walk's.
        public static readonly (double X, double Z, double YawDegrees) Track = (1.0, -1.0, 30.0);
        public static readonly (double X, double Z, double YawDegrees) FirstWalk = (2.0, 3.0, 90.0);
        public static readonly (double X, double Z, double YawDegrees) SecondWalk = (-1.0, 8.0, -30.0);

        // Seconds after a jump before its frames are compared: the frame that lands it.
        public const double Settle = 0.05;

        // (e), (f): 2 cm and 2° on top of what a frame's travel explains (the clips read between their 120 fps keys; float
        // transforms). Not placing the character (scene offsets) is off by where it started, metres; continuing from where it
        // was after a jump is off by the whole Walk's travel since the jump's time.
        public const double Slack = 0.02;
        public const double Degrees = 2.0;

        /// <summary>The track's offset ∘ a clip's, as x, z and yaw (radians): where the clip starts the character (its root motion counts from its first frame).</summary>
        public static (double X, double Z, double Yaw) Placed((double X, double Z, double YawDegrees) clip)
        {
            double t = Track.YawDegrees * Math.PI / 180, c = Math.Cos(t), s = Math.Sin(t);
            return (Track.X + c * clip.X + s * clip.Z, Track.Z - s * clip.X + c * clip.Z, t + clip.YawDegrees * Math.PI / 180);
        }

        /// <summary>
        /// (e) In the first recorded frame at or after <paramref name="clipStart"/> (before any jump), the character stands within
        /// <paramref name="fastest"/> × the time since the clip's start + <see cref="Slack"/> of <paramref name="expected"/>, and faces
        /// it within <see cref="Degrees"/> + the turn a walk makes in that time (at most 90°/s).
        /// </summary>
        public static void StartsAtTheOffset(IReadOnlyList<TrackMotionFrame> frames, double clipStart, (double X, double Z, double Yaw) expected, double fastest, string what,
            List<string> failures, TextWriter log)
        {
            for (int i = 0; i < frames.Count; i++)
            {
                if (i > 0 && frames[i].Time < frames[i - 1].Time) break;
                if (frames[i].Time < clipStart) continue;
                FigurePlace at = frames[i].Figures[0];
                double since = frames[i].Time - clipStart;
                double off = Math.Sqrt((at.X - expected.X) * (at.X - expected.X) + (at.Z - expected.Z) * (at.Z - expected.Z));
                double turned = Math.Abs(RootPlacement.WrapYaw(at.Yaw - expected.Yaw)) * 180 / Math.PI;
                double bound = fastest * since + Slack, turnBound = Degrees + 90 * since;
                log.WriteLine($"(e) {what}: at {frames[i].Time:F3} s the character stands {off:F4} m and {turned:F2}° from the track's and clip's offsets (bounds {bound:F4} m, {turnBound:F2}°)");
                if (off > bound) failures.Add($"(e) {what}: at {frames[i].Time:F3} s the character stands {off:F4} m from where the offsets place it ({expected.X:F3}, {expected.Z:F3}); expected at most {bound:F4} (is the track placing it?)");
                if (turned > turnBound) failures.Add($"(e) {what}: at {frames[i].Time:F3} s the character faces {turned:F2}° away from the offsets' {expected.Yaw * 180 / Math.PI:F1}°; expected at most {turnBound:F2}°");
                return;
            }

            failures.Add($"(e) {what}: no frame at or after {clipStart} s was recorded");
        }

        /// <summary>
        /// (f) Every frame after the playhead went back (from <see cref="Settle"/> after the jump to <see cref="FirstEnd"/>) stands
        /// where the character stood at the same time before the jump — the two frames around that time before, read linearly —
        /// within the distance those two frames were apart + <see cref="Slack"/>, and faces the same way within <see cref="Degrees"/>.
        /// </summary>
        public static void StandsWhereItStoodAtTheSameTime(IReadOnlyList<TrackMotionFrame> frames, List<string> failures, TextWriter log)
        {
            int jump = -1;
            for (int i = 1; i < frames.Count && jump < 0; i++) if (frames[i].Time < frames[i - 1].Time) jump = i;
            if (jump < 0)
            {
                failures.Add("(f) the playhead never went back: no jump was recorded");
                return;
            }

            double worst = 0, worstTurn = 0;
            int compared = 0;
            for (int i = jump; i < frames.Count; i++)
            {
                if (i > jump && frames[i].Time < frames[i - 1].Time) break;
                double t = frames[i].Time;
                if (t < frames[jump].Time + Settle || t > FirstEnd) continue;
                for (int k = 1; k < jump; k++)
                {
                    if (!(frames[k - 1].Time <= t && frames[k].Time >= t)) continue;
                    FigurePlace a = frames[k - 1].Figures[0], b = frames[k].Figures[0], now = frames[i].Figures[0];
                    double span = frames[k].Time - frames[k - 1].Time, u = span > 0 ? (t - frames[k - 1].Time) / span : 0;
                    double x = a.X + u * (b.X - a.X), z = a.Z + u * (b.Z - a.Z), yaw = a.Yaw + u * RootPlacement.WrapYaw(b.Yaw - a.Yaw);
                    double apart = Math.Sqrt((b.X - a.X) * (b.X - a.X) + (b.Z - a.Z) * (b.Z - a.Z));
                    double off = Math.Sqrt((now.X - x) * (now.X - x) + (now.Z - z) * (now.Z - z)), turned = Math.Abs(RootPlacement.WrapYaw(now.Yaw - yaw)) * 180 / Math.PI;
                    worst = Math.Max(worst, off);
                    worstTurn = Math.Max(worstTurn, turned);
                    compared++;
                    if (off > apart + Slack) failures.Add($"(f) after the jump back, at {t:F3} s the character stands {off:F4} m from where it stood at that time before; expected at most {apart + Slack:F4}");
                    if (turned > Degrees) failures.Add($"(f) after the jump back, at {t:F3} s the character faces {turned:F2}° from how it faced at that time before; expected at most {Degrees}°");
                    break;
                }
            }

            if (compared == 0) failures.Add("(f) no frame after the jump back was compared (none between the jump's landing and the first Walk's end)");
            log.WriteLine($"(f) after the jump back: {compared} frames, at most {worst:F4} m and {worstTurn:F2}° from where the character stood at the same times before");
        }
    }
}
