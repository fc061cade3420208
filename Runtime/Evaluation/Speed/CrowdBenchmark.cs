using DeltaInterpolator.Core.Scheduling;
using System;
using System.Diagnostics;
using System.Threading;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;

namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>
    /// N characters all ask for a transition (30 model frames on average, 24–36, a quarter of them with 4 past
    /// keys and the rest with 10) in the same rendered frame at 60 fps. Measures the main thread's cost of the
    /// N requests, the wall time until every character has its first and then all of its network frames when
    /// decoding runs as fast as it can (batched), the inference cost per rendered frame while all play
    /// (the decoder's own work, batched vs one run per character, measured side by side with their frames
    /// interleaved over three rounds of requests, simulated clock, one frame decoded per character per
    /// rendered frame; the whole step with every player's playback beside it), and, on a real 60 fps clock
    /// with the worker thread, how many rendered frames held a pose and
    /// how many model frames arrived after playback needed them.
    /// </summary>
    public static class CrowdBenchmark
    {
        /// <summary>
        /// The largest crowd the benchmark builds (4 × the largest measured crowd): each character
        /// holds its poses, history and decoder buffers, and 100,000 ran out of memory.
        /// </summary>
        public const int MaxCharacters = 1024;

        /// <summary>Runs the benchmark; takes seconds.</summary>
        /// <param name="loadLazyModel">Loads a fresh model with its lazy graphs (each decoder owns and disposes one).</param>
        /// <param name="characters">1 to <see cref="MaxCharacters"/>.</param>
        public static CrowdTimings Run(Func<Inbetweener> loadLazyModel, int characters)
        {
            if (characters < 1 || characters > MaxCharacters) throw new ArgumentOutOfRangeException(nameof(characters), characters, $"expected 1 to {MaxCharacters} characters");
            var result = new CrowdTimings { Characters = characters };

            // 1. Real clock, worker thread: request cost, held frames, late frames.
            using (var worker = new WorkerThreadScheduler(loadLazyModel()))
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
                    double due = (crowd.Time + 1 / Crowd.Fps - start) * 1000;
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

                result.FrozenFrames = held - heldBefore;
                result.FramesLate = late - lateBefore;
            }

            // 2. As fast as it can: first frames and all frames of every character (batched).
            using (var decoder = new MainThreadScheduler(loadLazyModel(), framesPerRun: 1))
            {
                var crowd = new Crowd(decoder, characters);
                crowd.Warm();
                crowd.RequestAll();
                while (!crowd.AllDecoded) decoder.Batches.Pump(int.MaxValue);
                crowd.PlayFor(1.3);
                // The main thread's cost of the N requests (keys copied, localized, features and SLERP frames;
                // no network: that runs on the decoder), measured here where no worker thread shares the core.
                long r0 = Stopwatch.GetTimestamp();
                crowd.RequestAll();
                result.RequestMainThreadMs = Math.Round(Ms(r0), 4);
                long t0 = Stopwatch.GetTimestamp();
                double first = -1;
                while (true)
                {
                    decoder.Batches.Pump(int.MaxValue);
                    bool all = true, any = true;
                    foreach (TransitionPlayer p in crowd.Players)
                    {
                        any &= p.DecodedFrames > 0;
                        all &= p.DecodedFrames >= p.CurrentTransition!.MissingFrames;
                    }

                    if (any && first < 0) first = Ms(t0);
                    if (all) break;
                }

                result.AllFirstFramesMs = Math.Round(first, 3);
                result.AllFramesMs = Math.Round(Ms(t0), 3);
            }

            // 3. Inference per rendered frame while all play, simulated 60 fps clock: batched vs one run per character,
            // side by side (their frames interleaved, so that whatever else the machine does weighs on both alike).
            var costs = FrameCost(loadLazyModel, characters);
            result.FrameMsBatched = Math.Round(costs.BatchedInference, 4);
            result.StepMsBatched = Math.Round(costs.BatchedStep, 4);
            result.FrameMsUnbatched = Math.Round(costs.UnbatchedInference, 4);
            result.StepMsUnbatched = Math.Round(costs.UnbatchedStep, 4);
            return result;
        }

        /// <summary>Rounds of requests whose frames are timed: one second of rendered frames each.</summary>
        private const int FrameCostRounds = 3;

        // Per rendered frame while all play: the decoder's work (its pumps: gather, run, scatter) and the whole step
        // (that and every player's playback, which batching does not change). Two identical crowds, one decoding every
        // character's work in one run per graph and shape, the other one run per character, stepped in turn frame by
        // frame over FrameCostRounds rounds of simultaneous requests.
        private static (double BatchedInference, double BatchedStep, double UnbatchedInference, double UnbatchedStep) FrameCost(Func<Inbetweener> loadLazyModel, int characters)
        {
            using var batched = new MainThreadScheduler(loadLazyModel(), 256, framesPerRun: 1) { TokensPerFrame = int.MaxValue };
            using var unbatched = new MainThreadScheduler(loadLazyModel(), 1, framesPerRun: 1) { TokensPerFrame = int.MaxValue };
            var crowds = new[] { new Crowd(batched, characters), new Crowd(unbatched, characters) };
            var decoders = new[] { batched, unbatched };
            foreach (Crowd crowd in crowds)
            {
                crowd.Warm();
                // A first round creates the batch tensors and bindings; the later ones are measured.
                crowd.RequestAll();
                crowd.PlayFor(1.3);
            }

            var steps = new double[2];
            var pumped = new long[2];
            int frames = 0;
            for (int round = 0; round < FrameCostRounds; round++)
            {
                foreach (Crowd crowd in crowds) crowd.RequestAll();
                double end = crowds[0].Time + 1.0;
                while (crowds[0].Time < end)
                {
                    for (int k = 0; k < 2; k++)
                    {
                        long p0 = decoders[k].Batches.PumpTicks;
                        long t0 = Stopwatch.GetTimestamp();
                        crowds[k].Step();
                        steps[k] += Ms(t0);
                        pumped[k] += decoders[k].Batches.PumpTicks - p0;
                    }

                    frames++;
                }
            }

            double Per(long ticks) => ticks * 1000.0 / Stopwatch.Frequency / frames;
            return (Per(pumped[0]), steps[0] / frames, Per(pumped[1]), steps[1] / frames);
        }

        private static double Ms(long since) => (Stopwatch.GetTimestamp() - since) * 1000.0 / Stopwatch.Frequency;
    }
}
