using System;
using System.Threading;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Runs the network on the calling (main) thread for engines whose workers must stay there (Unity
    /// Sentis), without stalling it: once per rendered frame (at the first player's frame) it gathers the
    /// pending work of every player into batched runs bounded by <see cref="TokensPerFrame"/>, and with a
    /// backend whose bindings are asynchronous (<see cref="IAsyncInferenceBinding"/>) it schedules them and
    /// collects the results in a later frame. A frame whose network output is not there yet shows the
    /// request's SLERP pose (<see cref="TransitionPlayer"/>).
    /// </summary>
    public sealed class MainThreadDecoder : TransitionDecoder
    {
        private readonly BatchScheduler _scheduler;
        private double _lastPump = double.NaN;
        private int _tokensPerFrame = 512;
        private int _framesPerJob = 1;

        /// <summary>Creates the decoder; it owns <paramref name="inbetweener"/>.</summary>
        /// <param name="inbetweener">The model.</param>
        /// <param name="maxBatch">Most transitions per run (1: one run per request and frame, unbatched).</param>
        /// <param name="framesPerRun">Missing frames each transition decodes per run (default 4: a run whose results arrive a few
        /// frames later, on an asynchronous engine, still keeps ahead of playback).</param>
        public MainThreadDecoder(Inbetweener inbetweener, int maxBatch = 256, int framesPerRun = 4)
            : base(inbetweener)
        {
            _scheduler = new BatchScheduler(inbetweener, maxBatch, useAsync: true, framesPerRun: framesPerRun);
        }

        /// <summary>
        /// Most work one rendered frame schedules, in tokens: a request's keys cost P + 1, a decoded frame 1.
        /// At least one row runs per frame. Lower spreads a burst of requests over more frames (each shows
        /// SLERP until its frames arrive); default 512.
        /// </summary>
        public int TokensPerFrame
        {
            get => _tokensPerFrame;
            set => _tokensPerFrame = value >= 1 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "expected at least 1 token per frame");
        }

        /// <summary>Frame runs per playing transition and rendered frame, at most (default 1; each decodes the constructor's frames per run).</summary>
        public int FramesPerJob
        {
            get => _framesPerJob;
            set => _framesPerJob = value >= 1 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "expected at least 1");
        }

        /// <summary>Tokens the last <see cref="Pump()"/> scheduled.</summary>
        public int LastFrameTokens { get; private set; }

        internal BatchScheduler Scheduler => _scheduler;

        /// <summary>
        /// Stopwatch ticks spent in pumps so far (gathering inputs, running graphs, scattering results): the
        /// decoder's own work, which the crowd benchmark reports per rendered frame.
        /// </summary>
        public long PumpTicks => _scheduler.PumpTicks;

        /// <summary>
        /// Collects finished runs and schedules new ones within <paramref name="tokenBudget"/> tokens (one frame per
        /// run), instead of <see cref="TokensPerFrame"/>: a benchmark drains every request at once with
        /// <see cref="int.MaxValue"/>. Returns the tokens scheduled.
        /// </summary>
        public int Pump(int tokenBudget) => _scheduler.Pump(tokenBudget);

        /// <inheritdoc />
        public override void Dispose()
        {
            _scheduler.Dispose();
            Inbetweener.Dispose();
        }

        /// <summary>
        /// One frame's work for every player: collects finished runs and schedules new ones within
        /// <see cref="TokensPerFrame"/>. Players call it at their first <see cref="TransitionPlayer.BeginFrame"/>
        /// of each frame time; call it yourself to run the work at another point of the frame.
        /// </summary>
        public void Pump()
        {
            LastFrameTokens = _scheduler.Pump(_tokensPerFrame, _framesPerJob);
        }

        internal override void Start(TransitionJob job)
        {
            job.Reset();
            _scheduler.Add(job);
        }

        internal override void Need(TransitionJob job, int frames, double time)
        {
            job.Needed = frames;
            if (time.Equals(_lastPump)) return;
            _lastPump = time;
            Pump();
        }

        internal override bool Drain(TransitionJob job, int millisecondsTimeout)
        {
            int start = Environment.TickCount;
            var spin = new SpinWait();
            while (job.Decoded < job.Transition.MissingFrames && job.Error == null && !job.Finished)
            {
                if (unchecked(Environment.TickCount - start) > millisecondsTimeout) return false;
                if (_scheduler.Pump(int.MaxValue, job.Transition.MissingFrames) == 0) spin.SpinOnce();
            }

            return job.Decoded >= job.Transition.MissingFrames;
        }
    }
}
