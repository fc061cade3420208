using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;
using static DeltaInterpolator.Tests.Blends.TransformOffsetChecks;

namespace DeltaInterpolator.Tests.Blends
{
    /// <summary>
    /// Issue 28, transform offsets: the PlayMode case cannot run here, but its checks can. A hand-written recording of the
    /// documented behaviour — a walk at 1.4 m/s along the placed facing from each clip's offset, the gap walked across, the
    /// playhead set back from 2.2 s to 0.4 s and the character put back where it stood then — passes at 30, 60 and 144 fps;
    /// a character left where it started (scene offsets) fails (e), and one that walks on from where it was after the jump fails (f).
    /// </summary>
    [TestFixture]
    public sealed class TransformOffsetChecksTests
    {
        public enum Fault
        {
            None,
            NotPlaced,
            ContinuesAfterTheJump,
        }

        private const double Speed = 1.4;

        [TestCase(30.0, Fault.None, 0, 0)]
        [TestCase(60.0, Fault.None, 0, 0)]
        [TestCase(144.0, Fault.None, 0, 0)]
        [TestCase(60.0, Fault.NotPlaced, 1, 0)]
        [TestCase(60.0, Fault.ContinuesAfterTheJump, 0, 1)]
        public void EachCheckPassesTheDocumentedBehaviourAndFailsItsFault(double fps, Fault fault, int e, int f)
        {
            List<TrackMotionFrame> frames = Record(fps, fault);
            var first = new List<string>();
            var second = new List<string>();
            StartsAtTheOffset(frames, 0, Placed(FirstWalk), 1.5 * Speed, "the first Walk", first, TestContext.Out);
            StartsAtTheOffset(frames, SecondStart, Placed(SecondWalk), 1.5 * Speed, "the second Walk", first, TestContext.Out);
            StandsWhereItStoodAtTheSameTime(frames, second, TestContext.Out);
            foreach (string failure in first) TestContext.WriteLine(failure);
            foreach (string failure in second) TestContext.WriteLine(failure);
            Assert.That((Math.Sign(first.Count), Math.Sign(second.Count)), Is.EqualTo((e, f)), $"{fault} at {fps} fps: (e), (f) failed");
        }

        [Test]
        public void ARecordingWithoutAJumpIsSaid()
        {
            List<TrackMotionFrame> frames = Record(60.0, Fault.None);
            var played = new List<TrackMotionFrame>();
            foreach (TrackMotionFrame frame in frames)
            {
                if (played.Count > 0 && frame.Time < played[played.Count - 1].Time) break;
                played.Add(frame);
            }

            var failures = new List<string>();
            StandsWhereItStoodAtTheSameTime(played, failures, TextWriter.Null);
            Assert.That(failures, Has.Count.EqualTo(1).And.Some.Contains("never went back"));
        }

        /// <summary>
        /// The character at track time t as documented: on each Walk, from the clip's placement along its facing at
        /// <see cref="Speed"/>; in the gap, from the first Walk's end to the second's start in a straight line.
        /// </summary>
        private static (double X, double Z, double Yaw) Documented(double t)
        {
            (double X, double Z, double Yaw) Walk((double X, double Z, double Yaw) from, double seconds) =>
                (from.X + Math.Sin(from.Yaw) * Speed * seconds, from.Z + Math.Cos(from.Yaw) * Speed * seconds, from.Yaw);
            if (t <= FirstEnd) return Walk(Placed(FirstWalk), Math.Max(0, t));
            if (t >= SecondStart) return Walk(Placed(SecondWalk), t - SecondStart);
            var a = Walk(Placed(FirstWalk), FirstEnd);
            var b = Placed(SecondWalk);
            double u = (t - FirstEnd) / (SecondStart - FirstEnd);
            return (a.X + u * (b.X - a.X), a.Z + u * (b.Z - a.Z), a.Yaw + u * (b.Yaw - a.Yaw));
        }

        private static List<TrackMotionFrame> Record(double fps, Fault fault)
        {
            var frames = new List<TrackMotionFrame>();
            double dt = 1 / fps, time = 0;
            (double X, double Z, double Yaw) at = (5, 5, 200 * Math.PI / 180); // where the character stood before Play
            bool jumped = false;
            while (time <= SecondEnd + 1e-9)
            {
                (double X, double Z, double Yaw) next = Documented(time);
                if (fault == Fault.NotPlaced)
                {
                    // Scene offsets: the same moves, from where the character stood.
                    var origin = Documented(0);
                    next = (at.X + next.X - (frames.Count == 0 ? origin.X : Documented(frames[frames.Count - 1].Time).X),
                        at.Z + next.Z - (frames.Count == 0 ? origin.Z : Documented(frames[frames.Count - 1].Time).Z), next.Yaw);
                }
                else if (fault == Fault.ContinuesAfterTheJump && jumped)
                {
                    // After the jump the character walks on from where it was, by the clip's moves.
                    double previous = frames[frames.Count - 1].Time;
                    var move = Documented(time);
                    var before = Documented(Math.Max(0, previous < time ? previous : time - dt));
                    next = (at.X + move.X - before.X, at.Z + move.Z - before.Z, move.Yaw);
                }

                at = next;
                frames.Add(new TrackMotionFrame(time, new[] { new FigurePlace(at.X, at.Z, at.Yaw, at.X, 1.0, at.Z) }));
                if (!jumped && time >= JumpAt)
                {
                    jumped = true;
                    time = JumpBackTo;
                }
                else time += dt;
            }

            return frames;
        }
    }
}
