using System;
using System.Diagnostics;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
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
    /// </remarks>
    internal sealed class BatchScheduler : IDisposable
    {
        private readonly Inbetweener _inbetweener;
        private readonly ModelContract _contract;
        private readonly bool _lazy;
        private readonly bool _async;
        private readonly List<TransitionJob> _active = new List<TransitionJob>(256);
        private readonly Dictionary<int, Group> _groups = new Dictionary<int, Group>();
        private readonly List<Group> _groupList = new List<Group>();
        private readonly List<TransitionJob> _scratch = new List<TransitionJob>(256);

        /// <param name="inbetweener">The model (its keys and frame graphs when loaded).</param>
        /// <param name="maxBatch">Most rows per run (1: one request per run, the unbatched reference).</param>
        /// <param name="useAsync">Schedule runs and collect them in a later pump when the backend allows it.</param>
        /// <param name="lazy">Decode frame by frame with the lazy graphs (when loaded); false: whole transitions.</param>
        /// <param name="framesPerRun">Missing frames each row of a frame run decodes (consecutive, from the first not decoded): 1 on a
        /// worker thread; more when runs finish frames later (asynchronous engines), to keep ahead of playback.</param>
        public BatchScheduler(Inbetweener inbetweener, int maxBatch, bool useAsync, bool lazy = true, int framesPerRun = 1)
        {
            if (framesPerRun < 1) throw new ArgumentOutOfRangeException(nameof(framesPerRun), framesPerRun, "expected at least 1 frame per run");
            FramesPerRun = framesPerRun;
            _inbetweener = inbetweener;
            _contract = inbetweener.Contract;
            _lazy = lazy && inbetweener.SupportsLazyDecoding;
            _async = useAsync;
            if (maxBatch < 1) throw new ArgumentOutOfRangeException(nameof(maxBatch), maxBatch, "expected at least 1 row per run");
            MaxBatch = _contract.HasBatchAxis ? maxBatch : 1;
        }

        /// <summary>Missing frames one row of a frame run decodes.</summary>
        public int FramesPerRun { get; }

        /// <summary>Most rows per run (1 for contract version 1 graphs).</summary>
        public int MaxBatch { get; }

        /// <summary>True when frames are published one by one (lazy graphs).</summary>
        public bool Lazy => _lazy;

        /// <summary>Jobs started and not yet finished.</summary>
        public int ActiveCount => _active.Count;

        /// <summary>Network runs so far (all graphs).</summary>
        public long Runs { get; private set; }

        /// <summary>Rows run so far (keys rows + frame rows + whole transitions).</summary>
        public long Rows { get; private set; }

        /// <summary>Tokens scheduled so far (a keys row costs K, a frame row 1, a whole transition K + n).</summary>
        public long Tokens { get; private set; }

        /// <summary>Adds a job whose keys, features and SLERP frames are written (<see cref="TransitionJob.Reset"/> done).</summary>
        public void Add(TransitionJob job)
        {
            job.Sequence = _nextSequence++;
            _active.Add(job);
        }

        private long _nextSequence;

        /// <summary>
        /// One round of work: collects finished asynchronous runs, encodes the keys of new requests, and
        /// decodes up to <paramref name="framesPerJob"/> next frames of every encoded request, all within
        /// <paramref name="tokenBudget"/> (at least one row always runs, so work progresses).
        /// </summary>
        /// <returns>Tokens scheduled by this pump.</returns>
        public int Pump(int tokenBudget, int framesPerJob = 1)
        {
            long start = Stopwatch.GetTimestamp();
            try
            {
                return PumpRound(tokenBudget, framesPerJob);
            }
            finally
            {
                PumpTicks += Stopwatch.GetTimestamp() - start;
            }
        }

        /// <summary>
        /// <see cref="Stopwatch"/> ticks spent in <see cref="Pump"/> so far: gathering inputs, running the graphs and
        /// scattering the results — the decoding work itself, without the players' per-frame playback (for benchmarks;
        /// written by the thread that pumps).
        /// </summary>
        public long PumpTicks { get; private set; }

        private int PumpRound(int tokenBudget, int framesPerJob)
        {
            int spent = 0;
            Retire();
            for (int g = 0; g < _groupList.Count; g++) Collect(_groupList[g]);
            if (!_lazy)
            {
                spent = RunWhole(tokenBudget);
                Retire();
                return spent;
            }

            // Keys of new requests, oldest first, grouped by their number of past keys.
            for (int i = 0; i < _active.Count; i++)
            {
                TransitionJob job = _active[i];
                if (job.Encoded || job.InFlight || job.Cancelled) continue;
                Group group = GroupFor(job.Transition.PastFrames);
                if (group.KeysPending != null) continue;
                group.Scratch.Add(job);
            }

            for (int g = 0; g < _groupList.Count; g++)
            {
                Group group = _groupList[g];
                // One run per MaxBatch rows (all of them in one run when batched).
                while (group.Scratch.Count > 0 && group.KeysPending == null)
                {
                    int used = RunKeys(group, tokenBudget - spent, spent == 0);
                    if (used == 0) break;
                    spent += used;
                    group.Scratch.RemoveRange(0, Math.Min(group.Scratch.Count, used / (group.Past + 1)));
                }

                group.Scratch.Clear();
            }

            for (int round = 0; round < framesPerJob; round++)
            {
                int before = spent;
                // Due frames first (decoded ≤ needed), then those ahead of playback.
                for (int urgency = 0; urgency < 2; urgency++)
                {
                    for (int i = 0; i < _active.Count; i++)
                    {
                        TransitionJob job = _active[i];
                        if (!job.Encoded || job.InFlight || job.Cancelled || job.Error != null) continue;
                        int decoded = job.Decoded;
                        if (decoded >= job.Transition.MissingFrames) continue;
                        bool due = decoded <= job.Needed;
                        if (due != (urgency == 0)) continue;
                        Group group = GroupFor(job.Transition.PastFrames);
                        if (group.FramePending != null) continue;
                        group.Scratch.Add(job);
                    }
                }

                for (int g = 0; g < _groupList.Count; g++)
                {
                    Group group = _groupList[g];
                    while (group.Scratch.Count > 0 && group.FramePending == null)
                    {
                        int used = RunFrames(group, tokenBudget - spent, spent == 0);
                        if (used == 0) break;
                        spent += used;
                        group.Scratch.RemoveRange(0, Math.Min(group.Scratch.Count, used / FramesPerRun));
                    }

                    group.Scratch.Clear();
                }

                if (spent == before) break;
            }

            Retire();
            return spent;
        }

        /// <summary>Finishes every job (the decoder is being disposed).</summary>
        public void FinishAll()
        {
            foreach (TransitionJob job in _active) job.Finish();
            _active.Clear();
        }

        public void Dispose()
        {
            FinishAll();
            foreach (Group g in _groupList) g.Dispose();
            _groupList.Clear();
            _groups.Clear();
        }

        private void Retire()
        {
            int w = 0;
            for (int i = 0; i < _active.Count; i++)
            {
                TransitionJob job = _active[i];
                bool done = !job.InFlight && (job.Cancelled || job.Error != null || job.Decoded >= job.Transition.MissingFrames);
                if (done)
                {
                    job.Finish();
                    continue;
                }

                _active[w++] = job;
            }

            if (w < _active.Count) _active.RemoveRange(w, _active.Count - w);
        }

        private int RunWhole(int tokenBudget)
        {
            int spent = 0;
            for (int i = 0; i < _active.Count; i++)
            {
                TransitionJob job = _active[i];
                if (job.Cancelled || job.Decoded > 0 || job.Error != null) continue;
                Transition t = job.Transition;
                int cost = t.KeyFrameCount + t.MissingFrames;
                if (spent > 0 && spent + cost > tokenBudget) break;
                try
                {
                    _inbetweener.Inbetween(t);
                    job.Publish(t.MissingFrames);
                }
                catch (Exception e)
                {
                    job.Error = e;
                }

                spent += cost;
                Runs++;
                Rows++;
                Tokens += cost;
            }

            return spent;
        }

        private int RunKeys(Group group, int budget, bool first)
        {
            int k = group.Past + 1;
            int rows = Math.Min(group.Scratch.Count, MaxBatch);
            int fit = Math.Max(0, budget) / k;
            if (rows > fit) rows = first ? Math.Max(1, fit) : fit;
            rows = group.Ensure(rows);
            if (rows <= 0) return 0;
            GraphTensors tensors = group.Keys!;
            float[] features = tensors.KeyFeatures!.Floats!;
            int width = k * _contract.KeyFeatureSize;
            for (int r = 0; r < rows; r++)
            {
                TransitionJob job = group.Scratch[r];
                Array.Copy(job.KeyFeatures, 0, features, r * width, width);
                tensors.SetKeyRow(r, job.Transition.MissingFrames);
                group.KeysJobs[r] = job;
            }

            IInferenceBinding binding;
            try
            {
                binding = group.KeysBinding(rows, _inbetweener.KeysBackend!);
            }
            catch (Exception e)
            {
                Fail(group.KeysJobs, rows, e);
                return 0;
            }

            Runs++;
            Rows += rows;
            Tokens += rows * k;
            if (_async && binding is IAsyncInferenceBinding scheduled)
            {
                for (int r = 0; r < rows; r++) group.KeysJobs[r]!.InFlight = true;
                try
                {
                    scheduled.Schedule();
                }
                catch (Exception e)
                {
                    Fail(group.KeysJobs, rows, e);
                    return rows * k;
                }

                group.KeysPending = scheduled;
                group.KeysPendingRows = rows;
                return rows * k;
            }

            try
            {
                binding.Run();
            }
            catch (Exception e)
            {
                Fail(group.KeysJobs, rows, e);
                return rows * k;
            }

            ScatterKeys(group, rows);
            return rows * k;
        }

        private void ScatterKeys(Group group, int rows)
        {
            float[] memory = group.Keys!.KeyMemory!.Floats!;
            int size = group.MemorySize;
            for (int r = 0; r < rows; r++)
            {
                TransitionJob job = group.KeysJobs[r]!;
                group.KeysJobs[r] = null;
                job.InFlight = false;
                if (job.KeyMemory == null || job.KeyMemory.Length != size) job.KeyMemory = new float[size];
                Array.Copy(memory, r * size, job.KeyMemory, 0, size);
                job.Encoded = true;
            }
        }

        private int RunFrames(Group group, int budget, bool first)
        {
            int per = FramesPerRun;
            int rows = Math.Min(group.Scratch.Count, MaxBatch);
            int fit = Math.Max(0, budget) / per;
            if (rows > fit) rows = first ? Math.Max(1, fit) : fit;
            rows = group.Ensure(rows);
            if (rows <= 0) return 0;
            GraphTensors tensors = group.Frame!;
            float[] memory = tensors.KeyMemory!.Floats!;
            int size = group.MemorySize;
            for (int r = 0; r < rows; r++)
            {
                TransitionJob job = group.Scratch[r];
                // A row that already holds this request's key encoding (the same jobs in the same order as
                // the last run: the steady state of a playing crowd) is not copied again.
                if (!ReferenceEquals(group.RowOwner[r], job) || group.RowGeneration[r] != job.Generation)
                {
                    Array.Copy(job.KeyMemory!, 0, memory, r * size, size);
                    group.RowOwner[r] = job;
                    group.RowGeneration[r] = job.Generation;
                }

                int n = job.Transition.MissingFrames;
                int from = job.Decoded;
                tensors.SetKeyRow(r, n);
                // Frames from..from+N−1, the ones past the gap repeated as its last (computed, not used).
                long[] query = tensors.QueryFrameIndices!.Longs!;
                for (int q = 0; q < per; q++) query[r * per + q] = group.Past + Math.Min(from + q, n - 1);
                group.FrameJobs[r] = job;
                group.FrameIndex[r] = from;
            }

            IInferenceBinding binding;
            try
            {
                binding = group.FrameBinding(rows, _inbetweener.FrameBackend!);
            }
            catch (Exception e)
            {
                Fail(group.FrameJobs, rows, e);
                return 0;
            }

            Runs++;
            Rows += rows;
            Tokens += rows * per;
            if (_async && binding is IAsyncInferenceBinding scheduled)
            {
                for (int r = 0; r < rows; r++) group.FrameJobs[r]!.InFlight = true;
                try
                {
                    scheduled.Schedule();
                }
                catch (Exception e)
                {
                    Fail(group.FrameJobs, rows, e);
                    return rows * per;
                }

                group.FramePending = scheduled;
                group.FramePendingRows = rows;
                return rows * per;
            }

            try
            {
                binding.Run();
            }
            catch (Exception e)
            {
                Fail(group.FrameJobs, rows, e);
                return rows * per;
            }

            ScatterFrames(group, rows);
            return rows * per;
        }

        private void ScatterFrames(Group group, int rows)
        {
            GraphTensors tensors = group.Frame!;
            float[] root = tensors.RootPositionDelta!.Floats!;
            float[] rotation = tensors.Rotation6DDelta!.Floats!;
            for (int r = 0; r < rows; r++)
            {
                TransitionJob job = group.FrameJobs[r]!;
                group.FrameJobs[r] = null;
                job.InFlight = false;
                if (job.Cancelled) continue;
                int from = group.FrameIndex[r];
                Transition t = job.Transition;
                int per = FramesPerRun;
                for (int q = 0; q < per && from + q < t.MissingFrames; q++)
                {
                    _inbetweener.Decode(t, job.Localization, job.LocalRoot, job.Pairs, root, rotation, r * per + q, from + q);
                    job.Publish(from + q + 1);
                }
            }
        }

        private void Collect(Group group)
        {
            if (group.KeysPending != null)
            {
                bool done;
                try
                {
                    done = group.KeysPending.TryComplete();
                }
                catch (Exception e)
                {
                    Fail(group.KeysJobs, group.KeysPendingRows, e);
                    group.KeysPending = null;
                    done = false;
                }

                if (done)
                {
                    group.KeysPending = null;
                    ScatterKeys(group, group.KeysPendingRows);
                }
            }

            if (group.FramePending != null)
            {
                bool done;
                try
                {
                    done = group.FramePending.TryComplete();
                }
                catch (Exception e)
                {
                    Fail(group.FrameJobs, group.FramePendingRows, e);
                    group.FramePending = null;
                    done = false;
                }

                if (done)
                {
                    group.FramePending = null;
                    ScatterFrames(group, group.FramePendingRows);
                }
            }
        }

        private static void Fail(TransitionJob?[] jobs, int rows, Exception e)
        {
            for (int r = 0; r < rows; r++)
            {
                TransitionJob? job = jobs[r];
                if (job == null) continue;
                job.InFlight = false;
                job.Error = e;
                jobs[r] = null;
            }
        }

        private Group GroupFor(int past)
        {
            if (!_groups.TryGetValue(past, out Group? group))
            {
                group = new Group(_contract, past, MaxBatch, FramesPerRun);
                _groups.Add(past, group);
                _groupList.Add(group);
            }

            return group;
        }

        /// <summary>Batch tensors and bindings of one number of past keys (K = P + 1), grown to the largest batch seen.</summary>
        private sealed class Group : IDisposable
        {
            private readonly ModelContract _contract;
            private readonly int _maxBatch;
            private IInferenceBinding?[] _keysBindings = Array.Empty<IInferenceBinding?>();
            private IInferenceBinding?[] _frameBindings = Array.Empty<IInferenceBinding?>();

            private readonly int _framesPerRun;

            public Group(ModelContract contract, int past, int maxBatch, int framesPerRun)
            {
                _contract = contract;
                _framesPerRun = framesPerRun;
                _maxBatch = maxBatch;
                Past = past;
                ModelArchitecture a = contract.Architecture;
                MemorySize = a.Blocks * 2 * (past + 1) * a.Width;
                Scratch = new List<TransitionJob>(maxBatch);
            }

            public int Past { get; }

            public int MemorySize { get; }

            public int Capacity { get; private set; }

            public List<TransitionJob> Scratch { get; }

            public GraphTensors? Keys { get; private set; }

            public GraphTensors? Frame { get; private set; }

            public TransitionJob?[] KeysJobs { get; private set; } = Array.Empty<TransitionJob?>();

            public TransitionJob?[] FrameJobs { get; private set; } = Array.Empty<TransitionJob?>();

            public int[] FrameIndex { get; private set; } = Array.Empty<int>();

            public TransitionJob?[] RowOwner { get; private set; } = Array.Empty<TransitionJob?>();

            public int[] RowGeneration { get; private set; } = Array.Empty<int>();

            public IAsyncInferenceBinding? KeysPending { get; set; }

            public int KeysPendingRows { get; set; }

            public IAsyncInferenceBinding? FramePending { get; set; }

            public int FramePendingRows { get; set; }

            /// <summary>
            /// Grows the batch tensors to hold <paramref name="rows"/> rows (doubling, up to the most rows per
            /// run); returns the rows that fit (fewer while a scheduled run still uses the current tensors).
            /// </summary>
            public int Ensure(int rows)
            {
                if (rows <= Capacity) return rows;
                if (KeysPending != null || FramePending != null) return Capacity;
                int capacity = Math.Max(rows, Math.Min(_maxBatch, Math.Max(4, Capacity * 2)));
                DisposeBindings();
                // Placeholder gap 1 at creation: every row's gap and key frames are written when it is gathered.
                Keys = GraphTensors.Create(_contract, ModelGraphKind.Keys, Past, 1, 0, batch: capacity);
                GraphTensors frameKeys = GraphTensors.Create(_contract, ModelGraphKind.Keys, Past, 1, 0, batch: capacity);
                Frame = GraphTensors.ForFrame(_contract, frameKeys, 1);
                if (_framesPerRun > 1)
                {
                    // The frame graph's query axis is dynamic: N frames per row (indices set per row, beyond the placeholder gap).
                    frameKeys = GraphTensors.Create(_contract, ModelGraphKind.Keys, Past, _framesPerRun, 0, batch: capacity);
                    Frame = GraphTensors.ForFrame(_contract, frameKeys, _framesPerRun);
                }
                _keysBindings = new IInferenceBinding?[capacity + 1];
                _frameBindings = new IInferenceBinding?[capacity + 1];
                KeysJobs = new TransitionJob?[capacity];
                FrameJobs = new TransitionJob?[capacity];
                FrameIndex = new int[capacity];
                RowOwner = new TransitionJob?[capacity];
                RowGeneration = new int[capacity];
                Capacity = capacity;
                return rows;
            }

            public IInferenceBinding KeysBinding(int rows, IInferenceBackend backend) =>
                _keysBindings[rows] ??= Keys!.Prefix(rows).Bind(backend);

            public IInferenceBinding FrameBinding(int rows, IInferenceBackend backend) =>
                _frameBindings[rows] ??= Frame!.Prefix(rows).Bind(backend);

            public void Dispose() => DisposeBindings();

            private void DisposeBindings()
            {
                foreach (IInferenceBinding? b in _keysBindings) b?.Dispose();
                foreach (IInferenceBinding? b in _frameBindings) b?.Dispose();
                _keysBindings = Array.Empty<IInferenceBinding?>();
                _frameBindings = Array.Empty<IInferenceBinding?>();
            }
        }
    }
}
