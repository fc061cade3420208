using System;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// One keys run whose <c>key_memory</c> stays on the device: the handle, the requests of its rows (each with
    /// the generation it was encoded for), and frame tensors and bindings of its own, so that runs of different
    /// keys runs can be in flight together. Reused (with its tensors and bindings) after <see cref="Release"/>.
    /// </summary>
    internal sealed class DeviceRun : IDisposable
    {
        private readonly IDeviceTensorBinding?[] _bindings;
        private readonly int[] _generation;

        public DeviceRun(ModelContract contract, GraphTensors keys, int capacity, int framesPerRun)
        {
            Capacity = capacity;
            Frame = GraphTensors.ForDeviceFrame(contract, keys, capacity, framesPerRun);
            Requests = new TransitionRequest?[capacity];
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

        public TransitionRequest?[] Requests { get; }

        /// <summary>First missing frame each row of the run in flight decodes; −1 for a row whose frames are ignored.</summary>
        public int[] FrameIndex { get; }

        public IAsyncInferenceBinding? Pending { get; set; }

        public void Hold(int row, TransitionRequest request)
        {
            Requests[row] = request;
            _generation[row] = request.Generation;
            FrameIndex[row] = -1;
            Frame.SetKeyRow(row, request.Transition.MissingFrames);
        }

        /// <summary>True while row <paramref name="r"/>'s request still wants frames from this run.</summary>
        public bool Live(int r)
        {
            TransitionRequest? request = Requests[r];
            // Finished first: a request is reused (new generation) only after the scheduler finished it, and
            // that read orders the generation read after it.
            if (request == null || request.Finished || request.Generation != _generation[r]) return false;
            return !request.Cancelled && request.Error == null && request.Decoded < request.Transition.MissingFrames;
        }

        /// <summary>0: no row plays any more; 1: some row's next frame is due; 2: rows play, ahead of playback.</summary>
        public int Urgency()
        {
            int urgency = 0;
            for (int r = 0; r < Rows; r++)
            {
                if (!Live(r)) continue;
                TransitionRequest request = Requests[r]!;
                if (request.Decoded <= request.Needed) return 1;
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
                Requests[r] = null;
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
