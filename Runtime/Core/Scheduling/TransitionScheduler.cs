using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// Where a <see cref="Playback.TransitionPlayer"/>'s network work runs: <see cref="WorkerThreadScheduler"/> (a
    /// background thread; the main thread never waits) or <see cref="MainThreadScheduler"/> (on the main
    /// thread, a bounded amount of work per rendered frame, for engines that must run there). One decoder
    /// serves any number of players of the same model and runs all of their pending work in batches
    /// (one run per graph and number of past keys per round).
    /// </summary>
    public abstract class TransitionScheduler : IDisposable
    {
        private readonly RowDecoder _rows;

        internal TransitionScheduler(Inbetweener inbetweener)
        {
            Inbetweener = inbetweener ?? throw new ArgumentNullException(nameof(inbetweener));
            FrameRate = inbetweener.Contract.FramesPerSecond;
            _rows = new RowDecoder(inbetweener.Contract);
        }

        /// <summary>The model's contract (skeleton, trained ranges).</summary>
        public ModelContract Contract => Inbetweener.Contract;

        /// <summary>The model's frame rate (the contract's training fps).</summary>
        public double FrameRate { get; }

        internal Inbetweener Inbetweener { get; }

        /// <summary>Releases the scheduler and the <see cref="Inference.Inbetweener"/> it was given.</summary>
        public abstract void Dispose();

        /// <summary>
        /// Main thread, at the request: localizes the keys, builds their features and writes the SLERP
        /// pose of every missing frame (what a frame shows until its network output arrives). Cheap: no
        /// network run.
        /// </summary>
        internal void Prepare(TransitionRequest request)
        {
            Transition t = request.Transition;
            _rows.Localize(t, request.Keys, request.KeyFeatures);
            for (int k = 0; k < t.MissingFrames; k++)
            {
                _rows.Baseline(t, request.Keys, k, request.SlerpRoots, request.SlerpRotations);
            }
        }

        /// <summary>Starts decoding a prepared request (main thread).</summary>
        internal abstract void Start(TransitionRequest request);

        /// <summary>
        /// Each rendered frame (main thread): playback needs <paramref name="frames"/> decoded frames of
        /// <paramref name="request"/> by now; the next pump decodes the most urgent first. Never runs or waits for the network.
        /// </summary>
        internal static void Need(TransitionRequest request, int frames) => request.Needed = frames;

        /// <summary>
        /// One frame's network work for every character of this scheduler. Call it once per rendered frame from the
        /// one place that owns the frame (the Unity layer: before the characters' updates; a frame-loop test or a crowd:
        /// before its characters' frames), never from inside one character's frame. The main-thread scheduler runs
        /// its batches here within its token budget; the worker-thread one pumps on its own thread and does nothing.
        /// </summary>
        public abstract void Pump();

        /// <summary>The timing hook each stage of a pump reports to, on the thread that pumps (null: none).</summary>
        public abstract IScheduleTimer? Timer { get; set; }

        /// <summary>Blocks until <paramref name="request"/> is decoded or <paramref name="millisecondsTimeout"/> passes (cut-scenes, tests).</summary>
        internal abstract bool Drain(TransitionRequest request, int millisecondsTimeout);
    }
}
