using System;
using System.Collections.Generic;
using System.Threading;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Runs the network on one background thread for every player of a model, so that a request costs the
    /// main thread only the copy of its keys. With the lazy graphs it encodes the keys once and publishes
    /// the missing frames one by one in playing order (the first frame is ready after the keys run and one
    /// small frame run); without them it decodes the whole transition in one run. Requests are served in
    /// order; frames of a request that was superseded are not decoded.
    /// </summary>
    /// <remarks>
    /// The <see cref="Inference.Inbetweener"/> given is used only on the worker thread, so its backend must
    /// allow being called from a thread other than the one that created it (ONNX Runtime does; Unity
    /// Sentis does not: use <see cref="MainThreadDecoder"/> there). Dispose stops the thread and disposes
    /// the inbetweener.
    /// </remarks>
    public sealed class InferenceWorker : TransitionDecoder
    {
        private readonly Queue<TransitionJob> _queue = new Queue<TransitionJob>(64);
        private readonly Dictionary<long, LazyDecoder> _lazy = new Dictionary<long, LazyDecoder>();
        private readonly Thread _thread;
        private readonly bool _useLazy;
        private bool _stopping;

        /// <summary>Starts the worker thread.</summary>
        /// <param name="inbetweener">The model; owned by the worker from now on.</param>
        /// <param name="lazy">Decode frame by frame when the lazy graphs are loaded (default); false: whole transitions.</param>
        public InferenceWorker(Inbetweener inbetweener, bool lazy = true)
            : base(inbetweener)
        {
            _useLazy = lazy && inbetweener.SupportsLazyDecoding;
            _thread = new Thread(Loop) { IsBackground = true, Name = "DeltaInterpolator inference" };
            _thread.Start();
        }

        /// <summary>True when frames are published one by one (lazy graphs), false when whole transitions are.</summary>
        public bool DecodesLazily => _useLazy;

        /// <inheritdoc />
        public override void Dispose()
        {
            lock (_queue)
            {
                if (_stopping) return;
                _stopping = true;
                foreach (TransitionJob job in _queue) job.Finish();
                _queue.Clear();
                Monitor.PulseAll(_queue);
            }

            _thread.Join();
            Inbetweener.Dispose();
        }

        internal override void Start(TransitionJob job)
        {
            lock (_queue)
            {
                if (_stopping) throw new ObjectDisposedException(nameof(InferenceWorker));
                job.Reset();
                _queue.Enqueue(job);
                Monitor.Pulse(_queue);
            }
        }

        internal override void Ensure(TransitionJob job, int frames)
        {
            // Frames arrive from the worker; the player shows what is there and never waits.
        }

        private void Loop()
        {
            while (true)
            {
                TransitionJob job;
                lock (_queue)
                {
                    while (_queue.Count == 0 && !_stopping) Monitor.Wait(_queue);
                    if (_stopping) return;
                    job = _queue.Dequeue();
                }

                try
                {
                    if (!job.Cancelled) Decode(job);
                }
                catch (Exception e)
                {
                    job.Error = e;
                }
                finally
                {
                    job.Finish();
                }
            }
        }

        private void Decode(TransitionJob job)
        {
            var t = job.Transition;
            if (!_useLazy)
            {
                Inbetweener.Inbetween(t);
                job.Publish(t.MissingFrames);
                return;
            }

            long key = ((long)t.PastFrames << 32) | (uint)t.MissingFrames;
            if (!_lazy.TryGetValue(key, out LazyDecoder? lazy))
            {
                lazy = Inbetweener.CreateLazy(t.PastFrames, t.MissingFrames);
                _lazy.Add(key, lazy);
            }

            lazy.Begin(t);
            for (int k = 0; k < t.MissingFrames; k++)
            {
                if (job.Cancelled) return;
                lazy.DecodeFrame(k);
                job.Publish(k + 1);
            }
        }
    }
}
