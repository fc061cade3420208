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
    /// <para>When the keys and frame backends can keep a tensor on their device (<see cref="IDeviceTensorBackend"/>:
    /// Sentis on a GPU), <c>key_memory</c> never crosses to the host: each keys run's output stays on the device
    /// (one handle per keys run, a <see cref="DeviceRun"/>, released when none of its rows plays any more), and frames
    /// are batched per keys run instead of across runs: every frame run binds one keys run's device tensor and
    /// decodes all of its rows (a finished or superseded row's frames are computed and ignored), so no gather
    /// on the device is needed. Otherwise every row's key encoding is read back into <see cref="TransitionJob.KeyMemory"/>
    /// and gathered into one frame batch per number of past keys.</para>
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
        private readonly List<DeviceRun> _runScratch = new List<DeviceRun>(64);
        private readonly bool _device;

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
            _device = _lazy && inbetweener.KeysBackend is IDeviceTensorBackend && inbetweener.FrameBackend is IDeviceTensorBackend;
            if (maxBatch < 1) throw new ArgumentOutOfRangeException(nameof(maxBatch), maxBatch, "expected at least 1 row per run");
            MaxBatch = _contract.HasBatchAxis ? maxBatch : 1;
        }

        /// <summary>Missing frames one row of a frame run decodes.</summary>
        public int FramesPerRun { get; }

        /// <summary>Most rows per run (1 for contract version 1 graphs).</summary>
        public int MaxBatch { get; }

        /// <summary>True when frames are published one by one (lazy graphs).</summary>
        public bool Lazy => _lazy;

        /// <summary>
        /// True when <c>key_memory</c> stays on the engine's device (both lazy graphs' backends are
        /// <see cref="IDeviceTensorBackend"/>s): frames are batched per keys run.
        /// </summary>
        public bool KeepsKeyMemoryOnDevice => _device;

        /// <summary>Keys runs whose device <c>key_memory</c> is held now (some of their rows still play).</summary>
        public int DeviceRunsHeld
        {
            get
            {
                int n = 0;
                for (int g = 0; g < _groupList.Count; g++) n += _groupList[g].Runs.Count;
                return n;
            }
        }

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
            if (_device) ReleaseRuns();
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

            if (_device)
            {
                spent = RunDeviceFrames(tokenBudget, framesPerJob, spent);
                Retire();
                ReleaseRuns();
                return spent;
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

            ScatterKeys(group, rows, binding);
            return rows * k;
        }

        private void ScatterKeys(Group group, int rows, IInferenceBinding binding)
        {
            if (_device)
            {
                KeepKeysOnDevice(group, rows, (IDeviceTensorBinding)binding);
                return;
            }

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
            float[]? contacts = tensors.FootContacts?.Floats;
            for (int r = 0; r < rows; r++)
            {
                TransitionJob job = group.FrameJobs[r]!;
                group.FrameJobs[r] = null;
                job.InFlight = false;
                if (job.Cancelled) continue;
                DecodeRow(job, root, rotation, contacts, r, group.FrameIndex[r]);
            }
        }

        /// <summary>Decodes and publishes row <paramref name="r"/>'s frames from <paramref name="from"/> on (those within its gap).</summary>
        private void DecodeRow(TransitionJob job, float[] root, float[] rotation, float[]? contacts, int r, int from)
        {
            Transition t = job.Transition;
            int per = FramesPerRun;
            for (int q = 0; q < per && from + q < t.MissingFrames; q++)
            {
                _inbetweener.Decode(t, job.Localization, job.LocalRoot, job.Pairs, root, rotation, r * per + q, from + q);
                _inbetweener.CopyContacts(t, contacts, r * per + q, from + q, 1);
                job.Publish(from + q + 1);
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
                    IAsyncInferenceBinding binding = group.KeysPending!;
                    group.KeysPending = null;
                    ScatterKeys(group, group.KeysPendingRows, binding);
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

            for (int i = 0; i < group.Runs.Count; i++)
            {
                DeviceRun run = group.Runs[i];
                if (run.Pending == null) continue;
                bool done;
                try
                {
                    done = run.Pending.TryComplete();
                }
                catch (Exception e)
                {
                    run.Pending = null;
                    FailRun(run, e);
                    continue;
                }

                if (done)
                {
                    run.Pending = null;
                    ScatterRun(run);
                }
            }
        }

        /// <summary>A finished keys run on a device backend: its <c>key_memory</c> stays there, held by a <see cref="DeviceRun"/> of its rows.</summary>
        private void KeepKeysOnDevice(Group group, int rows, IDeviceTensorBinding binding)
        {
            IDeviceTensor memory;
            try
            {
                memory = binding.TakeOutput();
            }
            catch (Exception e)
            {
                Fail(group.KeysJobs, rows, e);
                return;
            }

            DeviceRun run = group.Rent(rows);
            run.Memory = memory;
            for (int r = 0; r < rows; r++)
            {
                TransitionJob job = group.KeysJobs[r]!;
                group.KeysJobs[r] = null;
                job.InFlight = false;
                run.Hold(r, job);
                job.Encoded = true;
            }
        }

        /// <summary>
        /// Frame runs of the keys runs held on the device, one per keys run with rows still playing (those whose
        /// frames are due first, then those ahead of playback, each in request order), within the budget (a run
        /// costs all of its rows).
        /// </summary>
        private int RunDeviceFrames(int tokenBudget, int framesPerJob, int spent)
        {
            for (int round = 0; round < framesPerJob; round++)
            {
                int before = spent;
                _runScratch.Clear();
                for (int urgency = 1; urgency <= 2; urgency++)
                {
                    for (int g = 0; g < _groupList.Count; g++)
                    {
                        List<DeviceRun> runs = _groupList[g].Runs;
                        for (int i = 0; i < runs.Count; i++)
                        {
                            if (runs[i].Pending == null && runs[i].Urgency() == urgency) _runScratch.Add(runs[i]);
                        }
                    }
                }

                for (int i = 0; i < _runScratch.Count; i++)
                {
                    DeviceRun run = _runScratch[i];
                    int cost = run.Rows * FramesPerRun;
                    if (spent > 0 && spent + cost > tokenBudget) continue;
                    spent += RunDeviceFrame(run);
                }

                _runScratch.Clear();
                if (spent == before) break;
            }

            return spent;
        }

        private int RunDeviceFrame(DeviceRun run)
        {
            int per = FramesPerRun;
            int rows = run.Rows;
            GraphTensors tensors = run.Frame;
            long[] query = tensors.QueryFrameIndices!.Longs!;
            long[] gap = tensors.GapLength.Longs!;
            int past = tensors.PastFrames;
            for (int r = 0; r < rows; r++)
            {
                int n = (int)gap[r];
                // A row that no longer plays asks for its last frame again (computed, not used).
                int from = run.Live(r) ? run.Jobs[r]!.Decoded : -1;
                run.FrameIndex[r] = from;
                int first = from < 0 ? n - 1 : from;
                for (int q = 0; q < per; q++) query[r * per + q] = past + Math.Min(first + q, n - 1);
            }

            IDeviceTensorBinding binding;
            try
            {
                binding = run.Binding(rows, (IDeviceTensorBackend)_inbetweener.FrameBackend!);
                binding.SetInput(run.Memory!);
            }
            catch (Exception e)
            {
                FailRun(run, e);
                return 0;
            }

            Runs++;
            Rows += rows;
            Tokens += rows * per;
            if (_async && binding is IAsyncInferenceBinding scheduled)
            {
                for (int r = 0; r < rows; r++)
                {
                    if (run.FrameIndex[r] >= 0) run.Jobs[r]!.InFlight = true;
                }

                try
                {
                    scheduled.Schedule();
                }
                catch (Exception e)
                {
                    FailRun(run, e);
                    return rows * per;
                }

                run.Pending = scheduled;
                return rows * per;
            }

            try
            {
                binding.Run();
            }
            catch (Exception e)
            {
                FailRun(run, e);
                return rows * per;
            }

            ScatterRun(run);
            return rows * per;
        }

        private void ScatterRun(DeviceRun run)
        {
            float[] root = run.Frame.RootPositionDelta!.Floats!;
            float[] rotation = run.Frame.Rotation6DDelta!.Floats!;
            float[]? contacts = run.Frame.FootContacts?.Floats;
            for (int r = 0; r < run.Rows; r++)
            {
                int from = run.FrameIndex[r];
                if (from < 0) continue;
                run.FrameIndex[r] = -1;
                TransitionJob job = run.Jobs[r]!;
                job.InFlight = false;
                if (job.Cancelled) continue;
                DecodeRow(job, root, rotation, contacts, r, from);
            }
        }

        private static void FailRun(DeviceRun run, Exception e)
        {
            for (int r = 0; r < run.Rows; r++)
            {
                if (run.FrameIndex[r] < 0) continue;
                run.FrameIndex[r] = -1;
                TransitionJob job = run.Jobs[r]!;
                job.InFlight = false;
                job.Error = e;
            }
        }

        /// <summary>Releases the device <c>key_memory</c> of every keys run none of whose rows plays any more.</summary>
        private void ReleaseRuns()
        {
            for (int g = 0; g < _groupList.Count; g++)
            {
                Group group = _groupList[g];
                for (int i = group.Runs.Count - 1; i >= 0; i--)
                {
                    DeviceRun run = group.Runs[i];
                    if (run.Pending == null && run.Urgency() == 0) group.Release(i);
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
                group = new Group(_contract, past, MaxBatch, FramesPerRun, _device);
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
            private readonly bool _device;
            private readonly List<DeviceRun> _free = new List<DeviceRun>();

            public Group(ModelContract contract, int past, int maxBatch, int framesPerRun, bool device)
            {
                _contract = contract;
                _device = device;
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

            /// <summary>Keys runs held on the device (device backends only), oldest first.</summary>
            public List<DeviceRun> Runs { get; } = new List<DeviceRun>();

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
                KeysJobs = new TransitionJob?[capacity];
                _keysBindings = new IInferenceBinding?[capacity + 1];
                Capacity = capacity;
                // On a device backend frames run per keys run, each with tensors of its own (DeviceRun).
                if (_device) return rows;
                GraphTensors frameKeys = GraphTensors.Create(_contract, ModelGraphKind.Keys, Past, 1, 0, batch: capacity);
                Frame = GraphTensors.ForFrame(_contract, frameKeys, 1);
                if (_framesPerRun > 1)
                {
                    // The frame graph's query axis is dynamic: N frames per row (indices set per row, beyond the placeholder gap).
                    frameKeys = GraphTensors.Create(_contract, ModelGraphKind.Keys, Past, _framesPerRun, 0, batch: capacity);
                    Frame = GraphTensors.ForFrame(_contract, frameKeys, _framesPerRun);
                }
                _frameBindings = new IInferenceBinding?[capacity + 1];
                FrameJobs = new TransitionJob?[capacity];
                FrameIndex = new int[capacity];
                RowOwner = new TransitionJob?[capacity];
                RowGeneration = new int[capacity];
                return rows;
            }

            public IInferenceBinding KeysBinding(int rows, IInferenceBackend backend) =>
                _keysBindings[rows] ??= _device ? Keys!.Prefix(rows).BindOnDevice((IDeviceTensorBackend)backend, TensorNames.KeyMemory) : Keys!.Prefix(rows).Bind(backend);

            /// <summary>A free <see cref="DeviceRun"/> for a keys run of <paramref name="rows"/> rows (the smallest that fits, or a new one), added to <see cref="Runs"/>.</summary>
            public DeviceRun Rent(int rows)
            {
                int best = -1;
                for (int i = 0; i < _free.Count; i++)
                {
                    if (_free[i].Capacity >= rows && (best < 0 || _free[i].Capacity < _free[best].Capacity)) best = i;
                }

                DeviceRun run;
                if (best >= 0)
                {
                    run = _free[best];
                    _free.RemoveAt(best);
                }
                else
                {
                    int capacity = 1;
                    while (capacity < rows) capacity *= 2;
                    run = new DeviceRun(_contract, Keys!, Math.Min(capacity, Capacity), _framesPerRun);
                }

                run.Rows = rows;
                Runs.Add(run);
                return run;
            }

            /// <summary>Releases <see cref="Runs"/>[<paramref name="index"/>]'s device tensor and keeps the run for reuse.</summary>
            public void Release(int index)
            {
                DeviceRun run = Runs[index];
                Runs.RemoveAt(index);
                run.Release();
                _free.Add(run);
            }

            public IInferenceBinding FrameBinding(int rows, IInferenceBackend backend) =>
                _frameBindings[rows] ??= Frame!.Prefix(rows).Bind(backend);

            public void Dispose()
            {
                DisposeBindings();
                foreach (DeviceRun run in Runs) run.Dispose();
                foreach (DeviceRun run in _free) run.Dispose();
                Runs.Clear();
                _free.Clear();
            }

            private void DisposeBindings()
            {
                foreach (IInferenceBinding? b in _keysBindings) b?.Dispose();
                foreach (IInferenceBinding? b in _frameBindings) b?.Dispose();
                _keysBindings = Array.Empty<IInferenceBinding?>();
                _frameBindings = Array.Empty<IInferenceBinding?>();
            }
        }

        /// <summary>
        /// One keys run whose <c>key_memory</c> stays on the device: the handle, the requests of its rows (each with
        /// the generation it was encoded for), and frame tensors and bindings of its own, so that runs of different
        /// keys runs can be in flight together. Reused (with its tensors and bindings) after <see cref="Release"/>.
        /// </summary>
        private sealed class DeviceRun : IDisposable
        {
            private readonly IDeviceTensorBinding?[] _bindings;
            private readonly int[] _generation;

            public DeviceRun(ModelContract contract, GraphTensors keys, int capacity, int framesPerRun)
            {
                Capacity = capacity;
                Frame = GraphTensors.ForDeviceFrame(contract, keys, capacity, framesPerRun);
                Jobs = new TransitionJob?[capacity];
                FrameIndex = new int[capacity];
                _generation = new int[capacity];
                _bindings = new IDeviceTensorBinding?[capacity + 1];
                for (int r = 0; r < capacity; r++) FrameIndex[r] = -1;
            }

            public int Capacity { get; }

            /// <summary>Rows of the keys run (all of them decode in each frame run).</summary>
            public int Rows { get; set; }

            /// <summary>The keys run's <c>key_memory</c> on the device, [Rows, R, 2, K, D].</summary>
            public IDeviceTensor? Memory { get; set; }

            /// <summary>Frame graph tensors (gap lengths per row written at <see cref="Hold"/>).</summary>
            public GraphTensors Frame { get; }

            public TransitionJob?[] Jobs { get; }

            /// <summary>First missing frame each row of the run in flight decodes; −1 for a row whose frames are ignored.</summary>
            public int[] FrameIndex { get; }

            public IAsyncInferenceBinding? Pending { get; set; }

            public void Hold(int row, TransitionJob job)
            {
                Jobs[row] = job;
                _generation[row] = job.Generation;
                FrameIndex[row] = -1;
                Frame.SetKeyRow(row, job.Transition.MissingFrames);
            }

            /// <summary>True while row <paramref name="r"/>'s request still wants frames from this run.</summary>
            public bool Live(int r)
            {
                TransitionJob? job = Jobs[r];
                // Finished first: a job is reused (new generation) only after the scheduler finished it, and
                // that read orders the generation read after it.
                if (job == null || job.Finished || job.Generation != _generation[r]) return false;
                return !job.Cancelled && job.Error == null && job.Decoded < job.Transition.MissingFrames;
            }

            /// <summary>0: no row plays any more; 1: some row's next frame is due; 2: rows play, ahead of playback.</summary>
            public int Urgency()
            {
                int urgency = 0;
                for (int r = 0; r < Rows; r++)
                {
                    if (!Live(r)) continue;
                    TransitionJob job = Jobs[r]!;
                    if (job.Decoded <= job.Needed) return 1;
                    urgency = 2;
                }

                return urgency;
            }

            public IDeviceTensorBinding Binding(int rows, IDeviceTensorBackend backend) =>
                _bindings[rows] ??= Frame.Prefix(rows).BindOnDevice(backend, TensorNames.KeyMemory);

            public void Release()
            {
                Memory?.Dispose();
                Memory = null;
                Pending = null;
                for (int r = 0; r < Rows; r++)
                {
                    Jobs[r] = null;
                    FrameIndex[r] = -1;
                }

                Rows = 0;
            }

            public void Dispose()
            {
                Release();
                foreach (IDeviceTensorBinding? b in _bindings) b?.Dispose();
                Array.Clear(_bindings, 0, _bindings.Length);
            }
        }
    }
}
