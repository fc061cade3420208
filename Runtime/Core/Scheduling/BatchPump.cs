using System;
using System.Collections.Generic;
using System.Diagnostics;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// Gathers every character's pending network work into as few runs as possible: in one
    /// <see cref="Pump"/>, the keys of all new requests with the same number of past keys run as one batch
    /// of the keys graph, and the next missing frame of every playing transition with that number of past
    /// keys runs as one batch of the frame graph (rows may differ in gap length and frame). Results are
    /// scattered back into each request's own buffers. A budget in tokens (a keys row costs K = P + 1, a
    /// frame row 1) bounds the work one pump schedules, so a burst of requests spreads over frames instead
    /// of stalling one; the most urgent frames (those playback needs soonest) go first.
    /// </summary>
    /// <remarks>
    /// <para>Used from one thread (a worker's, or the main thread's). Allocation-free once the batch
    /// capacity and the bindings for the batch sizes seen have been created.</para>
    /// <para>With <see cref="IAsyncInferenceBinding"/> backends (and <c>useAsync</c>) a run is scheduled in
    /// one pump and collected in a later one, so the calling thread never waits for the engine.</para>
    /// <para>Contract version 1 graphs have no batch axis: they run one request per run (batch 1), as do
    /// models without the lazy graphs (one whole-transition run per request).</para>
    /// <para>How requests become runs is the pump's <see cref="RunStrategy"/>, chosen here once: whole transitions
    /// (<see cref="WholeTransitionRuns"/>), lazy frames with <c>key_memory</c> read back to the host
    /// (<see cref="HostFrameRuns"/>) or kept on the engine's device (<see cref="DeviceFrameRuns"/>); which rows run is
    /// <see cref="BatchPlanner"/>'s; every row becomes a frame through the model's one <see cref="RowDecoder"/>.</para>
    /// </remarks>
    internal sealed class BatchPump : IDisposable
    {
        private readonly RunStrategy _strategy;
        private readonly RowDecoder _rows;
        private readonly Dictionary<int, BatchBuffers> _buffers = new Dictionary<int, BatchBuffers>();
        private long _nextSequence;

        /// <param name="model">The model (its keys and frame graphs when loaded).</param>
        /// <param name="maxBatch">Most rows per run (1: one request per run, the unbatched reference).</param>
        /// <param name="useAsync">Schedule runs and collect them in a later pump when the backend allows it.</param>
        /// <param name="lazy">Decode frame by frame with the lazy graphs (when loaded); false: whole transitions.</param>
        /// <param name="framesPerRun">Missing frames each row of a frame run decodes (consecutive, from the first not decoded): 1 on a
        /// worker thread; more when runs finish frames later (asynchronous engines), to keep ahead of playback.</param>
        public BatchPump(Inbetweener model, int maxBatch, bool useAsync, bool lazy = true, int framesPerRun = 1)
        {
            if (framesPerRun < 1) throw new ArgumentOutOfRangeException(nameof(framesPerRun), framesPerRun, "expected at least 1 frame per run");
            if (maxBatch < 1) throw new ArgumentOutOfRangeException(nameof(maxBatch), maxBatch, "expected at least 1 row per run");
            FramesPerRun = framesPerRun;
            Model = model;
            Contract = model.Contract;
            Async = useAsync;
            Lazy = lazy && model.SupportsLazyDecoding;
            KeepsKeyMemoryOnDevice = Lazy && model.KeysBackend is IDeviceTensorBackend && model.FrameBackend is IDeviceTensorBackend;
            MaxBatch = Contract.HasBatchAxis ? maxBatch : 1;
            _rows = new RowDecoder(Contract);
            _strategy = !Lazy ? new WholeTransitionRuns(this) : KeepsKeyMemoryOnDevice ? new DeviceFrameRuns(this) : (RunStrategy)new HostFrameRuns(this);
        }

        /// <summary>Missing frames one row of a frame run decodes.</summary>
        public int FramesPerRun { get; }

        /// <summary>Most rows per run (1 for contract version 1 graphs).</summary>
        public int MaxBatch { get; }

        /// <summary>True when frames are published one by one (lazy graphs).</summary>
        public bool Lazy { get; }

        /// <summary>
        /// True when <c>key_memory</c> stays on the engine's device (both lazy graphs' backends are
        /// <see cref="IDeviceTensorBackend"/>s): frames are batched per keys run.
        /// </summary>
        public bool KeepsKeyMemoryOnDevice { get; }

        /// <summary>Keys runs whose device <c>key_memory</c> is held now (some of their rows still play).</summary>
        public int DeviceRunsHeld
        {
            get
            {
                int n = 0;
                for (int g = 0; g < Buffers.Count; g++) n += Buffers[g].Runs.Count;
                return n;
            }
        }

        /// <summary>Requests started and not yet finished.</summary>
        public int ActiveCount => Active.Count;

        /// <summary>Network runs so far (all graphs).</summary>
        public long Runs { get; private set; }

        /// <summary>Rows run so far (keys rows + frame rows + whole transitions).</summary>
        public long Rows { get; private set; }

        /// <summary>Tokens scheduled so far (a keys row costs K, a frame row 1, a whole transition K + n).</summary>
        public long Tokens { get; private set; }

        /// <summary>
        /// Key encodings copied from a request into a row of a frame batch so far (host key memory): at a request's first
        /// frame run, and again only when it has to change rows.
        /// </summary>
        public long KeyMemoryCopies { get; private set; }

        /// <summary>
        /// <see cref="Stopwatch"/> ticks spent in <see cref="Pump"/> so far: gathering inputs, running the graphs and
        /// scattering the results — the decoding work itself, without the players' per-frame playback (for benchmarks;
        /// written by the thread that pumps).
        /// </summary>
        public long PumpTicks { get; private set; }

        /// <summary>The timing hook each stage of a pump reports to (null: none).</summary>
        public IScheduleTimer? Timer { get; set; }

        /// <summary>The model whose graphs the strategies run.</summary>
        internal Inbetweener Model { get; }

        internal ModelContract Contract { get; }

        /// <summary>Runs are scheduled and collected in a later pump when the binding allows it.</summary>
        internal bool Async { get; }

        /// <summary>Requests started and not finished, oldest first.</summary>
        internal List<TransitionRequest> Active { get; } = new List<TransitionRequest>(256);

        /// <summary>The batch buffers of every number of past keys seen, in the order first seen.</summary>
        internal List<BatchBuffers> Buffers { get; } = new List<BatchBuffers>();

        /// <summary>Adds a request whose keys, features and SLERP frames are written (<see cref="TransitionRequest.Reset"/> done).</summary>
        public void Add(TransitionRequest request)
        {
            request.Sequence = _nextSequence++;
            Active.Add(request);
        }

        /// <summary>
        /// One round of work: collects finished asynchronous runs, encodes the keys of new requests, and
        /// decodes up to <paramref name="framesPerRequest"/> next frames of every encoded request, all within
        /// <paramref name="tokenBudget"/> (at least one row always runs, so work progresses).
        /// </summary>
        /// <returns>Tokens scheduled by this pump.</returns>
        public int Pump(int tokenBudget, int framesPerRequest = 1)
        {
            long start = Stopwatch.GetTimestamp();
            try
            {
                Retire();
                Timer?.Begin(ScheduleStage.Collect);
                for (int g = 0; g < Buffers.Count; g++) _strategy.Collect(Buffers[g]);
                _strategy.Release();
                Timer?.End(ScheduleStage.Collect);
                int spent = _strategy.Run(tokenBudget, framesPerRequest);
                Retire();
                _strategy.Release();
                return spent;
            }
            finally
            {
                PumpTicks += Stopwatch.GetTimestamp() - start;
            }
        }

        /// <summary>Finishes every request (the scheduler is being disposed).</summary>
        public void FinishAll()
        {
            foreach (TransitionRequest request in Active) request.Finish();
            Active.Clear();
        }

        public void Dispose()
        {
            FinishAll();
            foreach (BatchBuffers b in Buffers) b.Dispose();
            Buffers.Clear();
            _buffers.Clear();
        }

        /// <summary>Counts one key encoding copied into a frame batch row.</summary>
        internal void CountKeyMemoryCopy() => KeyMemoryCopies++;

        /// <summary>Counts one run of <paramref name="rows"/> rows costing <paramref name="tokens"/>.</summary>
        internal void Count(int rows, int tokens)
        {
            Runs++;
            Rows += rows;
            Tokens += tokens;
        }

        /// <summary>
        /// Counts a bound run of <paramref name="rows"/> requests (<paramref name="tokens"/>) and runs it here, or schedules
        /// it where the pump is asynchronous and the binding can be (its requests are then in flight). A failure to run or
        /// schedule ends the run's requests with it. Key runs and frame runs launch alike; only their outputs differ.
        /// </summary>
        /// <returns>True when it ran here: the caller scatters its outputs. False when it was scheduled (<paramref name="pending"/>) or failed.</returns>
        internal bool RunOrSchedule(IInferenceBinding binding, TransitionRequest?[] requests, int rows, int tokens, out IAsyncInferenceBinding? pending)
        {
            pending = null;
            Count(rows, tokens);
            if (Async && binding is IAsyncInferenceBinding scheduled)
            {
                for (int r = 0; r < rows; r++) requests[r]!.InFlight = true;
                try
                {
                    scheduled.Schedule();
                }
                catch (Exception e)
                {
                    Fail(requests, rows, e);
                    return false;
                }

                pending = scheduled;
                return false;
            }

            try
            {
                binding.Run();
            }
            catch (Exception e)
            {
                Fail(requests, rows, e);
                return false;
            }

            return true;
        }

        /// <summary>Whether a scheduled run is over; one that failed ends its first <paramref name="rows"/> requests with the error.</summary>
        /// <returns>True when it finished or failed (it is no longer pending); <paramref name="finished"/>: it finished, so its outputs can be scattered.</returns>
        internal static bool IsOver(IAsyncInferenceBinding pending, TransitionRequest?[] requests, int rows, out bool finished)
        {
            try
            {
                finished = pending.TryComplete();
                return finished;
            }
            catch (Exception e)
            {
                Fail(requests, rows, e);
                finished = false;
                return true;
            }
        }

        /// <summary>
        /// Decodes row <paramref name="r"/> of a frame run (its <see cref="FramesPerRun"/> output rows) into the request's
        /// frames from <paramref name="from"/> on (those within its gap) and publishes each.
        /// </summary>
        internal void Publish(TransitionRequest request, GraphTensors outputs, int r, int from)
        {
            Transition t = request.Transition;
            int per = FramesPerRun;
            int joints = Contract.JointCount;
            for (int q = 0; q < per && from + q < t.MissingFrames; q++)
            {
                _rows.Decode(t, request.Keys, OutputRow.Of(outputs, r * per + q, joints), from + q, t.RootPositions, t.LocalRotations, request.SlerpRotations);
                request.Publish(from + q + 1);
            }
        }

        /// <summary>The batch buffers of requests with <paramref name="past"/> past keys (created at the first).</summary>
        internal BatchBuffers BuffersFor(int past)
        {
            if (!_buffers.TryGetValue(past, out BatchBuffers? buffers))
            {
                buffers = new BatchBuffers(Contract, past, MaxBatch, FramesPerRun, KeepsKeyMemoryOnDevice);
                _buffers.Add(past, buffers);
                Buffers.Add(buffers);
            }

            return buffers;
        }

        /// <summary>Ends the first <paramref name="rows"/> requests of a failed run with <paramref name="e"/>.</summary>
        internal static void Fail(TransitionRequest?[] requests, int rows, Exception e)
        {
            for (int r = 0; r < rows; r++)
            {
                TransitionRequest? request = requests[r];
                if (request == null) continue;
                request.InFlight = false;
                request.Error = e;
                requests[r] = null;
            }
        }

        private void Retire()
        {
            int w = 0;
            for (int i = 0; i < Active.Count; i++)
            {
                TransitionRequest request = Active[i];
                if (BatchPlanner.IsDone(request))
                {
                    request.Finish();
                    continue;
                }

                Active[w++] = request;
            }

            if (w < Active.Count) Active.RemoveRange(w, Active.Count - w);
        }
    }
}
