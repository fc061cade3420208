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
    /// (the decoder's own work, batched vs one run per character, simulated clock, one frame decoded per
    /// character per rendered frame; the whole step with every player's playback beside it), and, on a real 60 fps clock with the worker thread, how many rendered frames held a pose and
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
            using (var worker = new InferenceWorker(loadLazyModel()))
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
            using (var decoder = new MainThreadDecoder(loadLazyModel(), framesPerRun: 1))
            {
                var crowd = new Crowd(decoder, characters);
                crowd.Warm();
                crowd.RequestAll();
                while (!crowd.AllDecoded) decoder.Scheduler.Pump(int.MaxValue);
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

                result.AllFirstFramesMs = Math.Round(first, 3);
                result.AllFramesMs = Math.Round(Ms(t0), 3);
            }

            // 3. Inference per rendered frame while all play, simulated 60 fps clock: batched vs one run per character.
            (double inference, double step) = FrameCost(loadLazyModel, characters, 256);
            result.FrameMsBatched = Math.Round(inference, 4);
            result.StepMsBatched = Math.Round(step, 4);
            (inference, step) = FrameCost(loadLazyModel, characters, 1);
            result.FrameMsUnbatched = Math.Round(inference, 4);
            result.StepMsUnbatched = Math.Round(step, 4);
            return result;
        }

        // Per rendered frame while all play: the decoder's work (its pumps: gather, run, scatter) and the whole step
        // (that and every player's playback, which batching does not change).
        private static (double Inference, double Step) FrameCost(Func<Inbetweener> loadLazyModel, int characters, int maxBatch)
        {
            using var decoder = new MainThreadDecoder(loadLazyModel(), maxBatch, framesPerRun: 1) { TokensPerFrame = int.MaxValue };
            var crowd = new Crowd(decoder, characters);
            crowd.Warm();
            // A first round creates the batch tensors and bindings; the second is measured.
            crowd.RequestAll();
            crowd.PlayFor(1.3);
            crowd.RequestAll();
            double total = 0;
            int frames = 0;
            long pumped = decoder.Scheduler.PumpTicks;
            double end = crowd.Time + 1.0;
            while (crowd.Time < end)
            {
                long t0 = Stopwatch.GetTimestamp();
                crowd.Step();
                total += Ms(t0);
                frames++;
            }

            double inference = (decoder.Scheduler.PumpTicks - pumped) * 1000.0 / Stopwatch.Frequency;
            return (inference / frames, total / frames);
        }

        private static double Ms(long since) => (Stopwatch.GetTimestamp() - since) * 1000.0 / Stopwatch.Frequency;
    }
}
