using System;
using System.Collections.Generic;
using System.Threading;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// Runs the network on one background thread for every player of a model, so that a request costs the
    /// main thread only the copy of its keys, their features and the SLERP frames. Each round gathers the
    /// work of every player into batched runs (<see cref="BatchPump"/>): the keys of all new requests,
    /// then the next missing frame of every playing transition, most urgent first. Without the lazy graphs
    /// it decodes whole transitions, one run each. Frames of a request that was superseded are not decoded.
    /// </summary>
    /// <remarks>
    /// The <see cref="Inference.Inbetweener"/> given is used only on the worker thread, so its backend must
    /// allow being called from a thread other than the one that created it (ONNX Runtime does; Unity
    /// Sentis does not: use <see cref="MainThreadScheduler"/> there). Dispose stops the thread and disposes
    /// the inbetweener.
    /// </remarks>
    public sealed class WorkerThreadScheduler : TransitionScheduler
    {
        private readonly Queue<TransitionRequest> _queue = new Queue<TransitionRequest>(256);
        private readonly BatchPump _pump;
        private readonly Thread _thread;
        private volatile int _tokensPerRound = 4096;
        private bool _stopping;

        /// <summary>Starts the worker thread.</summary>
        /// <param name="inbetweener">The model; owned by the worker from now on.</param>
        /// <param name="lazy">Decode frame by frame when the lazy graphs are loaded (default); false: whole transitions.</param>
        /// <param name="maxBatch">Most transitions per run (1: one run per request and frame, unbatched).</param>
        public WorkerThreadScheduler(Inbetweener inbetweener, bool lazy = true, int maxBatch = 256)
            : base(inbetweener)
        {
            _pump = new BatchPump(inbetweener, maxBatch, useAsync: false, lazy);
            _thread = new Thread(Loop) { IsBackground = true, Name = "DeltaInterpolator inference" };
            _thread.Start();
        }

        /// <summary>True when frames are published one by one (lazy graphs), false when whole transitions are.</summary>
        public bool DecodesLazily => _pump.Lazy;

        /// <summary>
        /// Most tokens one round of the worker runs (a request's keys cost P + 1, a frame 1; default 4096):
        /// a burst of requests is encoded over several rounds, with frames of playing transitions between them.
        /// </summary>
        public int TokensPerRound
        {
            get => _tokensPerRound;
            set => _tokensPerRound = value >= 1 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "expected at least 1 token per round");
        }

        /// <inheritdoc />
        public override void Dispose()
        {
            lock (_queue)
            {
                if (_stopping) return;
                _stopping = true;
                foreach (TransitionRequest request in _queue) request.Finish();
                _queue.Clear();
                Monitor.PulseAll(_queue);
            }

            _thread.Join();
            _pump.Dispose();
            Inbetweener.Dispose();
        }

        internal override void Start(TransitionRequest request)
        {
            lock (_queue)
            {
                if (_stopping) throw new ObjectDisposedException(nameof(WorkerThreadScheduler));
                request.Reset();
                _queue.Enqueue(request);
                Monitor.Pulse(_queue);
            }
        }

        /// <summary>Nothing: the worker thread pumps on its own, whenever requests wait (frames arrive from it; a player shows what is there, SLERP for the rest).</summary>
        public override void Pump()
        {
        }

        /// <inheritdoc />
        public override IScheduleTimer? Timer
        {
            get => _pump.Timer;
            set => _pump.Timer = value;
        }

        internal override bool Drain(TransitionRequest request, int millisecondsTimeout)
        {
            request.Needed = request.Transition.MissingFrames;
            var spin = new SpinWait();
            int start = Environment.TickCount;
            while (request.Decoded < request.Transition.MissingFrames && request.Error == null && !request.Finished)
            {
                if (unchecked(Environment.TickCount - start) > millisecondsTimeout) return false;
                spin.SpinOnce();
            }

            return request.Decoded >= request.Transition.MissingFrames;
        }

        private void Loop()
        {
            while (true)
            {
                lock (_queue)
                {
                    while (_queue.Count == 0 && _pump.ActiveCount == 0 && !_stopping) Monitor.Wait(_queue);
                    if (_stopping)
                    {
                        _pump.FinishAll();
                        return;
                    }

                    while (_queue.Count > 0) _pump.Add(_queue.Dequeue());
                }

                _pump.Pump(_tokensPerRound);
            }
        }
    }
}
