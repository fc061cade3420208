using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;

namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>
    /// The characters of the crowd benchmark on one scheduler, stepped on a simulated 60 fps clock: each plays
    /// its own animation (every joint swinging about its own axis, the root walking) and all of them request
    /// a transition in the same rendered frame. Public for the BenchmarkDotNet crowd benchmark (Tools~/Benchmarks).
    /// </summary>
    public sealed class Crowd
    {
        /// <summary>Rendered frames per second of the simulated clock.</summary>
        public const double Fps = 60;

        private readonly double[][] _roots;
        private readonly double[][] _rotations;
        private readonly int _bones;
        private int _frame;
        private int _round;
        private readonly TransitionScheduler _scheduler;

        /// <summary>Creates <paramref name="characters"/> players on <paramref name="decoder"/> (a quarter with 4 past keys).</summary>
        public Crowd(TransitionScheduler decoder, int characters)
        {
            _scheduler = decoder;
            ModelContract c = decoder.Contract;
            var map = new NamePoseConverter(c.Skeleton, c.UnitScale, c.Skeleton.Names);
            _bones = c.JointCount;
            _roots = new double[characters][];
            _rotations = new double[characters][];
            for (int i = 0; i < characters; i++)
            {
                // A quarter of the crowd asks with 4 past keys, the rest with the model's own context.
                var settings = new PlaybackSettings { BlendInSeconds = 0.1, PastFrames = i % 4 == 3 ? Math.Min(4, c.TrainingPastFrames.Max) : 0 };
                Players.Add(new TransitionPlayer(map, decoder, settings));
                _roots[i] = new double[3];
                _rotations[i] = new double[4 * _bones];
            }
        }

        /// <summary>One player per character.</summary>
        public List<TransitionPlayer> Players { get; } = new List<TransitionPlayer>();

        /// <summary>Seconds on the simulated clock.</summary>
        public double Time => _frame / Fps;

        /// <summary>True when every player has all the model frames of its current transition.</summary>
        public bool AllDecoded
        {
            get
            {
                foreach (TransitionPlayer p in Players)
                {
                    if (p.DecodedFrames < p.CurrentTransition!.MissingFrames) return false;
                }

                return true;
            }
        }

        /// <summary>Half a second of the characters' own animation, so every history is full.</summary>
        public void Warm() => PlayFor(0.5);

        /// <summary>Steps rendered frames for <paramref name="seconds"/> of the simulated clock.</summary>
        public void PlayFor(double seconds)
        {
            double end = Time + seconds;
            while (Time < end) Step();
        }

        /// <summary>One rendered frame: the scheduler's pump (the frame's owner runs it once, before the characters), then every character samples its animation and its player steps.</summary>
        public void Step()
        {
            _frame++;
            _scheduler.Pump();
            for (int i = 0; i < Players.Count; i++)
            {
                Pose(i, Time, _roots[i], _rotations[i]);
                var stream = new ArrayPoseStream(_roots[i], _rotations[i]);
                Players[i].Step(Time, ref stream);
            }
        }

        /// <summary>Every character requests a transition to a pose of its animation a few seconds ahead.</summary>
        public void RequestAll()
        {
            _round++;
            var root = new double[3];
            var rotations = new double[4 * _bones];
            for (int i = 0; i < Players.Count; i++)
            {
                Pose(i, Time + 2 + _round, root, rotations);
                // 24..36 model frames (0.8 to 1.2 s), 30 on average.
                Players[i].RequestTransition(root, rotations, (24 + (i * 7) % 13) / 30.0);
            }
        }

        /// <summary>A character's own animation: every joint swinging about its own axis, the root walking.</summary>
        private void Pose(int character, double time, double[] root, double[] rotations)
        {
            root[0] = 100 * time;
            root[1] = 90;
            root[2] = 10 * Math.Sin(time + character);
            for (int j = 0; j < _bones; j++)
            {
                double angle = 0.4 * Math.Sin(1.7 * time + 0.3 * j + character);
                double ax = Math.Sin(j + 1.0), ay = Math.Cos(2.0 * j), az = Math.Sin(3.0 * j + 0.5);
                double n = Math.Sqrt(ax * ax + ay * ay + az * az);
                double s = Math.Sin(angle / 2) / n;
                rotations[4 * j] = Math.Cos(angle / 2);
                rotations[4 * j + 1] = ax * s;
                rotations[4 * j + 2] = ay * s;
                rotations[4 * j + 3] = az * s;
            }
        }
    }
}
