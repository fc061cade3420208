using System;
using System.Threading;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// Runs the network on the calling (main) thread for engines whose workers must stay there (Unity
    /// Sentis), without stalling it: once per rendered frame (at the first player's frame) it gathers the
    /// pending work of every player into batched runs bounded by <see cref="TokensPerFrame"/>, and with a
    /// backend whose bindings are asynchronous (<see cref="IAsyncInferenceBinding"/>) it schedules them and
    /// collects the results in a later frame. A frame whose network output is not there yet shows the
    /// request's SLERP pose (<see cref="Playback.TransitionPlayer"/>).
    /// </summary>
    public sealed class MainThreadScheduler : TransitionScheduler
    {
        private readonly BatchPump _pump;
        private int _tokensPerFrame = 512;
        private int _framesPerRequest = 1;

        /// <summary>Creates the decoder; it owns <paramref name="inbetweener"/>.</summary>
        /// <param name="inbetweener">The model.</param>
        /// <param name="maxBatch">Most transitions per run (1: one run per request and frame, unbatched).</param>
        /// <param name="framesPerRun">Missing frames each transition decodes per run (default 4: a run whose results arrive a few
        /// frames later, on an asynchronous engine, still keeps ahead of playback).</param>
        public MainThreadScheduler(Inbetweener inbetweener, int maxBatch = 256, int framesPerRun = 4)
            : base(inbetweener)
        {
            _pump = new BatchPump(inbetweener, maxBatch, useAsync: true, framesPerRun: framesPerRun);
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
        public int FramesPerRequest
        {
            get => _framesPerRequest;
            set => _framesPerRequest = value >= 1 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "expected at least 1");
        }

        /// <summary>Tokens the last <see cref="Pump"/> scheduled.</summary>
        public int LastFrameTokens { get; private set; }

        internal BatchPump Batches => _pump;

        /// <inheritdoc />
        public override IScheduleTimer? Timer
        {
            get => _pump.Timer;
            set => _pump.Timer = value;
        }

        /// <inheritdoc />
        public override void Dispose()
        {
            _pump.Dispose();
            Inbetweener.Dispose();
        }

        /// <summary>
        /// One frame's work for every player: collects finished runs and schedules new ones within
        /// <see cref="TokensPerFrame"/>. The owner of the frame calls it once per rendered frame (see <see cref="TransitionScheduler.Pump"/>).
        /// </summary>
        public override void Pump()
        {
            LastFrameTokens = _pump.Pump(_tokensPerFrame, _framesPerRequest);
        }

        internal override void Start(TransitionRequest request)
        {
            request.Reset();
            _pump.Add(request);
        }

        internal override bool Drain(TransitionRequest request, int millisecondsTimeout)
        {
            int start = Environment.TickCount;
            var spin = new SpinWait();
            while (request.Decoded < request.Transition.MissingFrames && request.Error == null && !request.Finished)
            {
                if (unchecked(Environment.TickCount - start) > millisecondsTimeout) return false;
                if (_pump.Pump(int.MaxValue, request.Transition.MissingFrames) == 0) spin.SpinOnce();
            }

            return request.Decoded >= request.Transition.MissingFrames;
        }
    }
}
