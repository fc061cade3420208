using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// The batch buffers of one number of past keys (K = P + 1): the keys and frame tensors and their bindings
    /// per batch size, grown to the largest batch seen, and the rows of the runs in flight. The one cache of
    /// batch buffers; gap lengths and frame indices are written per row, so requests of any n share it.
    /// </summary>
    internal sealed class BatchBuffers : IDisposable
    {
        private readonly ModelContract _contract;
        private readonly int _maxBatch;
        private IInferenceBinding?[] _keysBindings = Array.Empty<IInferenceBinding?>();
        private IInferenceBinding?[] _frameBindings = Array.Empty<IInferenceBinding?>();

        private readonly int _framesPerRun;
        private readonly bool _device;
        private readonly List<DeviceRun> _free = new List<DeviceRun>();

        public BatchBuffers(ModelContract contract, int past, int maxBatch, int framesPerRun, bool device)
        {
            _contract = contract;
            _device = device;
            _framesPerRun = framesPerRun;
            _maxBatch = maxBatch;
            Past = past;
            ModelArchitecture a = contract.Architecture;
            MemorySize = a.Blocks * 2 * (past + 1) * a.Width;
            Scratch = new List<TransitionRequest>(maxBatch);
        }

        public int Past { get; }

        public int MemorySize { get; }

        public int Capacity { get; private set; }

        public List<TransitionRequest> Scratch { get; }

        /// <summary>Keys runs held on the device (device backends only), oldest first.</summary>
        public List<DeviceRun> Runs { get; } = new List<DeviceRun>();

        public GraphTensors? Keys { get; private set; }

        public GraphTensors? Frame { get; private set; }

        public TransitionRequest?[] KeysRequests { get; private set; } = Array.Empty<TransitionRequest?>();

        public TransitionRequest?[] FrameRequests { get; private set; } = Array.Empty<TransitionRequest?>();

        public int[] FrameIndex { get; private set; } = Array.Empty<int>();

        public TransitionRequest?[] RowOwner { get; private set; } = Array.Empty<TransitionRequest?>();

        public int[] RowGeneration { get; private set; } = Array.Empty<int>();

        /// <summary>Scratch rows for <see cref="HostFrameRuns"/>' placement of a frame run's requests (all null between runs).</summary>
        public TransitionRequest?[] Placement { get; private set; } = Array.Empty<TransitionRequest?>();

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
            KeysRequests = new TransitionRequest?[capacity];
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
            FrameRequests = new TransitionRequest?[capacity];
            FrameIndex = new int[capacity];
            RowOwner = new TransitionRequest?[capacity];
            RowGeneration = new int[capacity];
            Placement = new TransitionRequest?[capacity];
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
}
