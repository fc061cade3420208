using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Text.Json.Nodes;
using System.Threading;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.OnnxRuntime;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// `inbetween speed --characters N`: N characters all ask for a transition (30 model frames on average,
    /// 24–36, a quarter of them with 4 past keys and the rest with 10) in the same rendered frame at 60 fps.
    /// Measures the main thread's cost of the N requests, the wall time until every character has its first
    /// and then all of its network frames when decoding runs as fast as it can (batched), the inference cost
    /// per rendered frame while all play (batched vs one run per character, simulated clock, one frame
    /// decoded per character per rendered frame), and, on a real 60 fps clock with the worker thread, how
    /// many rendered frames held a pose and how many model frames arrived after playback needed them.
    /// </summary>
    internal static class CrowdBenchmark
    {
        private const double Fps = 60;

        public static JsonObject Run(string modelPath, OnnxRuntimeOptions options, int characters)
        {
            var result = new JsonObject { ["characters"] = characters };

            // 1. Real clock, worker thread: request cost, held frames, late frames.
            using (var worker = new InferenceWorker(OnnxRuntimeInbetweener.Load(modelPath, options, requireLazy: true)))
            {
                var crowd = new Crowd(worker, characters);
                crowd.Warm();
                // A first round warms the code paths and creates the jobs; the second is measured.
                crowd.RequestAll();
                crowd.PlayFor(0.1);
                foreach (TransitionPlayer p in crowd.Players) p.WaitUntilDecoded(60000);
                crowd.PlayFor(1.3);
                int heldBefore = 0, lateBefore = 0;
                foreach (TransitionPlayer p in crowd.Players)
                {
                    heldBefore += p.HeldFrames;
                    lateBefore += p.LateModelFrames;
                }

                var clock = Stopwatch.StartNew();
                double start = crowd.Time;
                crowd.RequestAll();
                double end = start + 1.3;
                while (crowd.Time < end)
                {
                    double due = (crowd.Time + 1 / Fps - start) * 1000;
                    // Sleep, not spin: on one core the worker needs the time.
                    while (clock.Elapsed.TotalMilliseconds < due) Thread.Sleep(due - clock.Elapsed.TotalMilliseconds > 1.5 ? 1 : 0);
                    crowd.Step();
                }

                int held = 0, late = 0;
                foreach (TransitionPlayer p in crowd.Players)
                {
                    held += p.HeldFrames;
                    late += p.LateModelFrames;
                }

                result["frozen_frames"] = held - heldBefore;
                result["frames_late"] = late - lateBefore;
            }

            // 2. As fast as it can: first frames and all frames of every character (batched).
            using (var decoder = new MainThreadDecoder(OnnxRuntimeInbetweener.Load(modelPath, options, requireLazy: true), framesPerRun: 1))
            {
                var crowd = new Crowd(decoder, characters);
                crowd.Warm();
                crowd.RequestAll();
                while (!AllDecoded(crowd)) decoder.Scheduler.Pump(int.MaxValue);
                crowd.PlayFor(1.3);
                // The main thread's cost of the N requests (keys copied, localized, features and SLERP frames;
                // no network: that runs on the decoder), measured here where no worker thread shares the core.
                long r0 = Stopwatch.GetTimestamp();
                crowd.RequestAll();
                result["request_main_thread_ms"] = Math.Round(Ms(r0), 4);
                long t0 = Stopwatch.GetTimestamp();
                double first = -1;
                while (true)
                {
                    decoder.Scheduler.Pump(int.MaxValue);
                    bool all = true, any = true;
                    foreach (TransitionPlayer p in crowd.Players)
                    {
                        any &= p.DecodedFrames > 0;
                        all &= p.DecodedFrames >= p.CurrentTransition!.MissingFrames;
                    }

                    if (any && first < 0) first = Ms(t0);
                    if (all) break;
                }

                result["all_first_frames_ms"] = Math.Round(first, 3);
                result["all_frames_ms"] = Math.Round(Ms(t0), 3);
            }

            // 3. Inference per rendered frame while all play, simulated 60 fps clock: batched vs one run per character.
            result["frame_ms_batched"] = Math.Round(FrameCost(modelPath, options, characters, 256), 4);
            result["frame_ms_unbatched"] = Math.Round(FrameCost(modelPath, options, characters, 1), 4);
            return result;
        }

        private static double FrameCost(string modelPath, OnnxRuntimeOptions options, int characters, int maxBatch)
        {
            using var decoder = new MainThreadDecoder(OnnxRuntimeInbetweener.Load(modelPath, options, requireLazy: true), maxBatch, framesPerRun: 1) { TokensPerFrame = int.MaxValue };
            var crowd = new Crowd(decoder, characters);
            crowd.Warm();
            // A first round creates the batch tensors and bindings; the second is measured.
            crowd.RequestAll();
            crowd.PlayFor(1.3);
            crowd.RequestAll();
            double total = 0;
            int frames = 0;
            double end = crowd.Time + 1.0;
            while (crowd.Time < end)
            {
                long t0 = Stopwatch.GetTimestamp();
                crowd.Step();
                total += Ms(t0);
                frames++;
            }

            return total / frames;
        }

        private static bool AllDecoded(Crowd crowd)
        {
            foreach (TransitionPlayer p in crowd.Players)
            {
                if (p.DecodedFrames < p.CurrentTransition!.MissingFrames) return false;
            }

            return true;
        }

        private static double Ms(long since) => (Stopwatch.GetTimestamp() - since) * 1000.0 / Stopwatch.Frequency;

        private sealed class Crowd
        {
            private readonly double[][] _roots;
            private readonly double[][] _rotations;
            private readonly int _bones;
            private int _frame;
            private int _round;

            public Crowd(TransitionDecoder decoder, int characters)
            {
                ModelContract c = decoder.Contract;
                var map = new NameJointMap(c.Skeleton, c.UnitScale, c.Skeleton.Names);
                _bones = c.JointCount;
                _roots = new double[characters][];
                _rotations = new double[characters][];
                for (int i = 0; i < characters; i++)
                {
                    var settings = new PlaybackSettings { BlendInSeconds = 0.1, PastFrames = i % 4 == 3 ? Math.Min(4, c.TrainingPastFrames.Max) : 0 };
                    Players.Add(new TransitionPlayer(map, decoder, settings));
                    _roots[i] = new double[3];
                    _rotations[i] = new double[4 * _bones];
                }
            }

            public List<TransitionPlayer> Players { get; } = new List<TransitionPlayer>();

            public double Time => _frame / Fps;

            public void Warm() => PlayFor(0.5);

            public void PlayFor(double seconds)
            {
                double end = Time + seconds;
                while (Time < end) Step();
            }

            public void Step()
            {
                _frame++;
                for (int i = 0; i < Players.Count; i++)
                {
                    Pose(i, Time, _roots[i], _rotations[i]);
                    var stream = new ArrayStream(_roots[i], _rotations[i]);
                    Players[i].Step(Time, ref stream);
                }
            }

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

        private struct ArrayStream : IPoseStream
        {
            private readonly double[] _root;
            private readonly double[] _rotations;

            public ArrayStream(double[] root, double[] rotations)
            {
                _root = root;
                _rotations = rotations;
            }

            public int BoneCount => _rotations.Length / 4;

            public Vector3D ReadRootPosition() => Vector3D.Read(_root, 0);

            public void WriteRootPosition(Vector3D position) => position.Write(_root, 0);

            public QuaternionD ReadLocalRotation(int bone) => QuaternionD.Read(_rotations, 4 * bone);

            public void WriteLocalRotation(int bone, QuaternionD rotation) => rotation.Write(_rotations, 4 * bone);
        }
    }
}
