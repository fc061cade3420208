using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Blends;

namespace DeltaInterpolator.Tests.Blends
{
    /// <summary>
    /// The verification track of <c>NeuralTrackRootMotionVerification</c> (Tests/PlayMode/Timeline) and what its recording
    /// must show. One Neural Animation Track plays Walk 0–<see cref="GapStart"/>, a gap, Walk again from
    /// <see cref="GapEnd"/> to <see cref="BlendEnd"/> and Jump from <see cref="BlendStart"/> to <see cref="End"/> (a blend
    /// over the second Walk's end) on the character; two tracks with one clip each play the second Walk and Jump alone on
    /// two twins. The checks: (a) <see cref="KeepsMovingThroughTheGap"/>, (b) <see cref="HipsDoNotJumpWhereSpansStartOrEnd"/>,
    /// (c) <see cref="PlaysOnFromWhereTheSpanLeftIt"/>; each bound's reason is beside its constant. Each check adds what it
    /// found wrong to a list (the PlayMode test asserts it empty) and writes what it measured to a log. Engine-free, so that
    /// <see cref="TrackMotionChecksTests"/> shows here that each check fails on the recording of the fault it is for.
    /// </summary>
    public static class TrackMotionChecks
    {
        /// <summary>The recording's figures: the character on the neural track, and the twins playing one clip each.</summary>
        public const int Character = 0, WalkTwin = 1, JumpTwin = 2;

        // The track, in seconds: the Demo's cuts (one 1.1 s gait cycle of Walk, 1.6 s of Jump) placed within their length.
        public const double GapStart = 1.1;   // Walk plays 0–1.1 s
        public const double GapEnd = 1.7;     // a 0.6 s gap (17 missing frames at the model's 30 fps); Walk again 1.7–2.8 s
        public const double BlendStart = 2.5; // Jump 2.5–4.1 s: a 0.3 s blend (8 missing frames) over the second Walk's end
        public const double BlendEnd = 2.8;
        public const double End = 4.1;

        // Seconds after a clip starts before its frames count as the clip's own.
        public const double Settle = 0.05;

        // The clips' own speeds are read from WalkFrom on: the first frame after Play can be long (the spans are baked inside
        // Play, and Unity caps that frame's delta time at 1/3 s by default), and a step over it is no walk frame.
        public const double WalkFrom = 0.35;

        // (a), (b): no step across or inside a span is more than 1.5 × the largest the clips make at the same frame length.
        // The model's first step in this gap continues the walk at 0.612 against its 0.580 per frame (GapRootTravelTests)
        // and a blend's step changes by at most 0.148 of 0.62 per model frame inside (BlendRootTravelTests): a quarter at
        // most; the rest is for game frames falling unevenly on the model's 30 fps frames. A pop (the travel applied twice,
        // a placement snapping back, the travel left in the hips) is a whole offset — tens of centimetres — in one frame.
        public const double StepMargin = 1.5;

        // (a): no frame inside the gap moves the character slower than 0.3 × the walk's mean speed. A gap with no root travel
        // (the track seeing no root motion in the clips, or the Animator ignoring the stream's velocity) stands still: 0.
        // 0.3, not nearer 1: the model's path between two walk frames may slow where its feet change over.
        public const double KeepsMoving = 0.3;

        // (b): 1 cm on top of the hips' bound: a span is read at the model's 30 fps between two frames and the clips at their
        // 120 fps keys, so the hips' first step into or out of a span may differ from the clips' by a sub-frame's motion
        // (about 1 cm at a walk's 1.4 m/s); a visible pop is larger.
        public const double HipsSlack = 0.01;

        // (c): after a span the character and its twin play the same clip at the same times, so their moves from a common
        // frame are the same up to float rounding at their different places: 1 cm and 1 % of the distance moved, 1° of turn.
        // Not continuing from where the span left it (snapping to the clip's or the timeline's origin) or carrying the
        // span's velocity on is off by the whole travel.
        public const double FollowSlack = 0.01;
        public const double FollowShare = 0.01;
        public const double FollowDegrees = 1.0;

        /// <summary>Near the track's end, or past it: the director holding its last time, or stopped or wrapped (its time going back).</summary>
        public static bool PlayedToTheEnd(IReadOnlyList<TrackMotionFrame> recorded)
        {
            int n = recorded.Count;
            return n > 0 && (recorded[n - 1].Time >= End - 0.1 || (n > 1 && recorded[n - 1].Time < recorded[n - 2].Time));
        }

        /// <summary>The frames until the director stopped or wrapped (its time going back).</summary>
        public static List<TrackMotionFrame> Played(IReadOnlyList<TrackMotionFrame> recorded)
        {
            var played = new List<TrackMotionFrame>();
            foreach (TrackMotionFrame f in recorded)
            {
                if (played.Count > 0 && f.Time < played[played.Count - 1].Time) break;
                played.Add(f);
            }

            return played;
        }

        /// <summary>
        /// (a) Per frame touching the gap the character moves at most <see cref="StepMargin"/> × the walk's fastest frame, and
        /// per frame inside it at least <see cref="KeepsMoving"/> × the walk's mean; the blend's frames at most
        /// <see cref="StepMargin"/> × the clips' fastest. The walk's and the jump's speeds are the character's own where the
        /// clips play alone.
        /// </summary>
        public static void KeepsMovingThroughTheGap(IReadOnlyList<TrackMotionFrame> frames, List<string> failures, TextWriter log)
        {
            List<double> walk = Speeds(frames, Character, hips: false, failures, (WalkFrom, GapStart), (GapEnd + Settle, BlendStart));
            List<double> jump = Speeds(frames, Character, hips: false, failures, (BlendEnd + Settle, End));
            if (walk.Count == 0 || jump.Count == 0) return;
            double walkMax = Max(walk), walkMean = Mean(walk), clipsMax = Math.Max(walkMax, Max(jump));
            log.WriteLine($"character's ground speed: walk mean {walkMean:F3} m/s, max {walkMax:F3}; jump max {Max(jump):F3}");
            double slowest = double.MaxValue, fastest = 0, fastestInBlend = 0;
            for (int i = 1; i < frames.Count; i++)
            {
                double t0 = frames[i - 1].Time, t1 = frames[i].Time;
                if (t1 - t0 <= 1e-6) continue;
                double speed = Step(frames, i, Character, hips: false) / (t1 - t0);
                if (t1 > GapStart && t0 < GapEnd)
                {
                    fastest = Math.Max(fastest, speed);
                    Expect(failures, speed <= StepMargin * walkMax, $"(a) no jump in the gap: the character moved at {speed:F3} m/s in the frame to {t1:F3} s; expected at most {StepMargin} × the walk's fastest {walkMax:F3}");
                    if (t0 >= GapStart && t1 <= GapEnd)
                    {
                        slowest = Math.Min(slowest, speed);
                        Expect(failures, speed >= KeepsMoving * walkMean, $"(a) the character keeps moving through the gap: {speed:F3} m/s in the frame to {t1:F3} s; expected at least {KeepsMoving} × the walk's mean {walkMean:F3} (does the Animator apply the track's root velocity?)");
                    }
                }

                if (t1 > BlendStart && t0 < BlendEnd)
                {
                    fastestInBlend = Math.Max(fastestInBlend, speed);
                    Expect(failures, speed <= StepMargin * clipsMax, $"(a) no jump in the blend: the character moved at {speed:F3} m/s in the frame to {t1:F3} s; expected at most {StepMargin} × the clips' fastest {clipsMax:F3}");
                }
            }

            Expect(failures, slowest < double.MaxValue, "frames inside the gap were recorded");
            log.WriteLine($"(a) in the gap: slowest {slowest:F3} m/s, fastest {fastest:F3}; in the blend: fastest {fastestInBlend:F3}");
        }

        /// <summary>
        /// (b) The frames that cross a span's start or end (and the next) move the hips at most <see cref="StepMargin"/> × the
        /// neighbouring clips' fastest hips at that frame's length, plus <see cref="HipsSlack"/>.
        /// </summary>
        public static void HipsDoNotJumpWhereSpansStartOrEnd(IReadOnlyList<TrackMotionFrame> frames, List<string> failures, TextWriter log)
        {
            double walk = Max(Speeds(frames, Character, hips: true, failures, (WalkFrom, GapStart), (GapEnd + Settle, BlendStart)));
            double both = Math.Max(walk, Max(Speeds(frames, Character, hips: true, failures, (BlendEnd + Settle, End))));
            foreach ((double at, double fastest, string what) in new[] { (GapStart, walk, "the gap's start"), (GapEnd, walk, "the gap's end"), (BlendStart, both, "the blend's start"), (BlendEnd, both, "the blend's end") })
            {
                bool crossed = false;
                for (int i = 1; i < frames.Count; i++)
                {
                    if (!(frames[i - 1].Time < at && frames[i].Time >= at)) continue;
                    crossed = true;
                    for (int k = i; k <= i + 1 && k < frames.Count; k++)
                    {
                        double dt = frames[k].Time - frames[k - 1].Time;
                        double step = Step(frames, k, Character, hips: true);
                        double bound = StepMargin * fastest * dt + HipsSlack;
                        log.WriteLine($"(b) {what}: the hips moved {step:F4} m in the frame to {frames[k].Time:F3} s (bound {bound:F4})");
                        Expect(failures, step <= bound, $"(b) the hips jump at {what}: {step:F4} m in the frame to {frames[k].Time:F3} s; expected at most {bound:F4} ({StepMargin} × the clips' hips at {fastest:F3} m/s × {dt:F4} s + {HipsSlack} m)");
                    }
                }

                Expect(failures, crossed, $"(b) a recorded frame crosses {what}");
            }
        }

        /// <summary>
        /// (c) From the first frame at or after <paramref name="from"/> to <paramref name="to"/>, the character's move in its own
        /// frame then is <paramref name="twin"/>'s, frame by frame (scene offsets: the clip's root motion from where the span
        /// left the character).
        /// </summary>
        public static void PlaysOnFromWhereTheSpanLeftIt(IReadOnlyList<TrackMotionFrame> frames, int twin, double from, double to, string what, List<string> failures, TextWriter log)
        {
            int r = -1;
            for (int i = 0; i < frames.Count && r < 0; i++) if (frames[i].Time >= from) r = i;
            Expect(failures, r >= 0, $"(c) frames of {what} were recorded");
            if (r < 0) return;
            double worst = 0, worstTurn = 0;
            int compared = 0;
            for (int i = r + 1; i < frames.Count && frames[i].Time <= to; i++)
            {
                (double side, double turn, double ahead) mine = Moved(frames, r, i, Character), theirs = Moved(frames, r, i, twin);
                double off = Math.Sqrt((mine.side - theirs.side) * (mine.side - theirs.side) + (mine.ahead - theirs.ahead) * (mine.ahead - theirs.ahead));
                double distance = Math.Sqrt(theirs.side * theirs.side + theirs.ahead * theirs.ahead);
                double turned = Math.Abs(RootPlacement.WrapYaw(mine.turn - theirs.turn)) * 180.0 / Math.PI;
                worst = Math.Max(worst, off);
                worstTurn = Math.Max(worstTurn, turned);
                compared++;
                Expect(failures, off <= FollowSlack + FollowShare * distance, $"(c) {what}: at {frames[i].Time:F3} s the character's move is {off:F4} m from its twin's (the clip alone; twin moved {distance:F3} m); expected at most {FollowSlack + FollowShare * distance:F4}");
                Expect(failures, turned <= FollowDegrees, $"(c) {what}: at {frames[i].Time:F3} s the character's turn is {turned:F2}° from its twin's; expected at most {FollowDegrees}°");
            }

            Expect(failures, compared > 0, $"(c) frames of {what} were compared");
            log.WriteLine($"(c) {what}: at most {worst:F4} m and {worstTurn:F3}° from the twin's own move");
        }

        // Ground speeds (m/s) of a figure (or its hips, in 3-D) over the frames wholly inside the given stretches of track time.
        private static List<double> Speeds(IReadOnlyList<TrackMotionFrame> frames, int figure, bool hips, List<string> failures, params (double From, double To)[] stretches)
        {
            var speeds = new List<double>();
            for (int i = 1; i < frames.Count; i++)
            {
                double t0 = frames[i - 1].Time, t1 = frames[i].Time;
                if (t1 - t0 <= 1e-6) continue;
                foreach ((double from, double to) in stretches)
                {
                    if (t0 >= from && t1 <= to) speeds.Add(Step(frames, i, figure, hips) / (t1 - t0));
                }
            }

            if (speeds.Count >= 5) return speeds;
            failures.Add($"only {speeds.Count} frames of the clips alone were recorded to measure their speed; expected 5 or more");
            return new List<double>();
        }

        // How far a figure's object moved over the ground, or its hips in space, from frame i - 1 to frame i.
        private static double Step(IReadOnlyList<TrackMotionFrame> frames, int i, int figure, bool hips)
        {
            FigurePlace a = frames[i - 1].Figures[figure], b = frames[i].Figures[figure];
            if (!hips) return Math.Sqrt((b.X - a.X) * (b.X - a.X) + (b.Z - a.Z) * (b.Z - a.Z));
            return Math.Sqrt((b.HipsX - a.HipsX) * (b.HipsX - a.HipsX) + (b.HipsY - a.HipsY) * (b.HipsY - a.HipsY) + (b.HipsZ - a.HipsZ) * (b.HipsZ - a.HipsZ));
        }

        // A figure's move from frame r to frame i in its own frame at r: sideways (+X of its frame), its turn (radians), ahead.
        private static (double side, double turn, double ahead) Moved(IReadOnlyList<TrackMotionFrame> frames, int r, int i, int figure)
        {
            FigurePlace a = frames[r].Figures[figure], b = frames[i].Figures[figure];
            double dx = b.X - a.X, dz = b.Z - a.Z, cos = Math.Cos(a.Yaw), sin = Math.Sin(a.Yaw);
            return (cos * dx - sin * dz, RootPlacement.WrapYaw(b.Yaw - a.Yaw), sin * dx + cos * dz);
        }

        // A failure says what was measured and the bound: the message names both sides of the comparison.
        private static void Expect(List<string> failures, bool holds, string what)
        {
            if (!holds) failures.Add(what);
        }


        private static double Max(List<double> values)
        {
            double max = 0;
            foreach (double v in values) max = Math.Max(max, v);
            return max;
        }

        private static double Mean(List<double> values)
        {
            double sum = 0;
            foreach (double v in values) sum += v;
            return sum / values.Count;
        }
    }
}
