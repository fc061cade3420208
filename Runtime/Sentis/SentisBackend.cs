#nullable enable
using DeltaInterpolator.Core.Scheduling;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using Unity.InferenceEngine;
using Unity.Jobs;
using Unity.Profiling;

namespace DeltaInterpolator.Sentis
{
    /// <summary>
    /// <see cref="IInferenceBackend"/> on Unity Sentis (<c>com.unity.ai.inference</c> ≥ 2.4.0): one
    /// <see cref="Worker"/> for one imported graph. <see cref="Bind"/> creates the Sentis input tensors
    /// once per request shape; every <see cref="IInferenceBinding.Run"/> uploads Core's arrays into them,
    /// schedules the worker and copies the outputs back into Core's arrays.
    /// </summary>
    /// <remarks>
    /// <para>A runtime Sentis <see cref="Model"/> carries no ONNX <c>metadata_props</c>: the caller passes
    /// the metadata captured when the model was imported (the model asset's contract), and
    /// <see cref="ModelContract.Read"/> checks it together with the graph's inputs as Sentis reports them.
    /// Sentis imports ONNX int64 tensors as 32-bit ints, so int64 inputs are reported as
    /// <see cref="TensorElementKind.Int64"/> and converted on upload. Sentis does not report output element
    /// types before a run, so outputs are described with the kinds the contract names and checked against
    /// the real tensors on every run (a mismatch throws).</para>
    /// <para>On <see cref="BackendType.CPU"/> (the default) outputs are read in place, without allocation
    /// in this class. Bindings are <see cref="IAsyncInferenceBinding"/>s: Core's frame scheduler
    /// (<c>MainThreadScheduler</c>) schedules a run in one frame (<c>Worker.Schedule</c>, then
    /// <c>Tensor.ReadbackRequest</c> on each output) and collects it in a later frame once
    /// <c>IsReadbackRequestDone</c>, so the main thread never waits for the Burst jobs or the GPU;
    /// <see cref="IInferenceBinding.Run"/> still runs and reads back at once. A scheduled run reads back
    /// copies of its outputs (<c>Worker.CopyOutput</c>), since the worker's own outputs last only until its
    /// next <c>Schedule</c>, and several bindings of one worker may be in flight. Not thread-safe:
    /// use a backend from the thread that created it (Unity's main thread for GPU backends).</para>
    /// <para>As an <see cref="IDeviceTensorBackend"/> it keeps the keys graph's <c>key_memory</c> on the
    /// worker's device: the keys run's output is copied there (<c>Worker.CopyOutput</c>) into a tensor Core
    /// holds by a handle, and the frame graph's runs take that tensor as their input (<c>Worker.SetInput</c>),
    /// with no readback or upload.</para>
    /// </remarks>
    public sealed class SentisBackend : IDeviceTensorBackend
    {
        private readonly Worker _worker;
        private readonly OpenBindings<Binding> _bindings = new OpenBindings<Binding>();

        private SentisBackend(Worker worker, BackendType backendType, ModelDescription description)
        {
            _worker = worker;
            BackendType = backendType;
            Description = description;
        }

        /// <inheritdoc />
        public ModelDescription Description { get; }

        /// <summary>The Sentis backend the worker runs on.</summary>
        public BackendType BackendType { get; }

        /// <summary>
        /// Loads one imported graph on a new worker.
        /// </summary>
        /// <param name="asset">The graph as Sentis imported it (an <c>.onnx</c> file in the project).</param>
        /// <param name="metadata">The graph's ONNX <c>metadata_props</c> as captured at import (key <c>deltainterp</c> holds the contract JSON).</param>
        /// <param name="source">The graph's name for messages, e.g. its asset path.</param>
        /// <param name="backendType">CPU (default, Burst) or a GPU backend.</param>
        /// <exception cref="ModelContractException">The asset is missing or Sentis cannot load it.</exception>
        public static SentisBackend Load(ModelAsset asset, IReadOnlyDictionary<string, string> metadata, string source, BackendType backendType = BackendType.CPU)
        {
            if (metadata == null) throw new ArgumentNullException(nameof(metadata));
            if (asset == null)
            {
                throw new ModelContractException(source, "no model asset was given", "expected the imported .onnx graph (assign it in the model asset)");
            }

            Model model;
            try
            {
                model = ModelLoader.Load(asset);
            }
            catch (Exception e) when (!(e is OutOfMemoryException))
            {
                throw new ModelContractException(source, "Sentis cannot load the imported graph (" + e.Message + ")",
                    "expected an .onnx file exported by `python3 -m deltainterp export` and imported by com.unity.ai.inference 2.4.0 or later; reimport it");
            }

            ModelDescription description = Describe(source, model, metadata);
            var worker = new Worker(model, backendType);
            return new SentisBackend(worker, backendType, description);
        }

        /// <inheritdoc />
        public IInferenceBinding Bind(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs)
        {
            _bindings.RequireOpen(nameof(SentisBackend));
            Binding binding = BindingTargets.Fill(new Binding(this, null), Description, inputs, outputs);
            _bindings.Add(binding);
            return binding;
        }

        /// <inheritdoc />
        public IDeviceTensorBinding BindOnDevice(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs, string onDevice)
        {
            _bindings.RequireOpen(nameof(SentisBackend));
            if (onDevice == null) throw new ArgumentNullException(nameof(onDevice));
            Binding binding = BindingTargets.Fill(new Binding(this, onDevice), Description, inputs, outputs);
            if (!binding.HasDeviceTensor)
            {
                binding.Dispose();
                throw new ArgumentException($"'{onDevice}' is neither an input nor an output of the binding", nameof(onDevice));
            }

            _bindings.Add(binding);
            return binding;
        }

        /// <summary>Disposes every open binding's tensors and the worker.</summary>
        public void Dispose()
        {
            if (!_bindings.Close()) return;
            _worker.Dispose();
        }

        private static ModelDescription Describe(string source, Model model, IReadOnlyDictionary<string, string> metadata)
        {
            var inputs = new List<TensorDescription>(model.inputs.Count);
            foreach (Model.Input input in model.inputs)
            {
                int[] dims = input.shape.ToIntArray();
                var shape = new long[dims == null ? 0 : dims.Length];
                for (int i = 0; i < shape.Length; i++) shape[i] = dims![i];
                inputs.Add(new TensorDescription(input.name, Kind(input.dataType), shape));
            }

            var outputs = new List<TensorDescription>(model.outputs.Count);
            foreach (Model.Output output in model.outputs)
            {
                outputs.Add(new TensorDescription(output.name, ContractKind(output.name), Array.Empty<long>()));
            }

            return new ModelDescription(source, inputs, outputs, metadata);
        }

        // Sentis stores ONNX int64 as 32-bit int; Core speaks the ONNX types of the contract.
        private static TensorElementKind Kind(DataType type) => type == DataType.Float ? TensorElementKind.Float32 : type == DataType.Int ? TensorElementKind.Int64 : TensorElementKind.Other;

        private static TensorElementKind ContractKind(string output)
        {
            switch (output)
            {
                case TensorNames.RootPositionDelta:
                case TensorNames.Rotation6DDelta:
                case TensorNames.KeyMemory:
                    return TensorElementKind.Float32;
                case TensorNames.ContractVersion:
                case TensorNames.JointCount:
                case TensorNames.KeyFeatureSize:
                    return TensorElementKind.Int64;
                default:
                    return TensorElementKind.Other;
            }
        }

        private static TensorShape Shape(InferenceTensor t)
        {
            var dims = new int[t.Shape.Length];
            for (int i = 0; i < dims.Length; i++) dims[i] = checked((int)t.Shape[i]);
            return new TensorShape(dims);
        }

        /// <summary>A tensor on the worker's device, held by Core (<see cref="IDeviceTensor"/>).</summary>
        private sealed class DeviceTensor : IDeviceTensor
        {
            public DeviceTensor(Tensor tensor)
            {
                Tensor = tensor;
            }

            public Tensor? Tensor { get; private set; }

            public void Dispose()
            {
                Tensor?.Dispose();
                Tensor = null;
            }
        }

        private sealed class Binding : IAsyncInferenceBinding, IDeviceTensorBinding, IBindingTarget
        {
            private readonly SentisBackend _owner;
            private readonly string? _onDevice;
            private readonly List<(InferenceTensor Core, Tensor<float>? Floats, Tensor<int>? Ints, int[]? Scratch, float[]? Staging)> _inputs = new List<(InferenceTensor, Tensor<float>?, Tensor<int>?, int[]?, float[]?)>();
            private readonly List<Tensor?> _copies = new List<Tensor?>();
            private bool _scheduled;
            private readonly List<InferenceTensor> _outputs = new List<InferenceTensor>();
            private bool _disposed;
            private bool _deviceInput;
            private bool _deviceOutput;
            private DeviceTensor? _input;
            private DeviceTensor? _output;

            public Binding(SentisBackend owner, string? onDevice)
            {
                _owner = owner;
                _onDevice = onDevice;
            }

            public bool HasDeviceTensor => _deviceInput || _deviceOutput;

            public void BindInput(InferenceTensor t)
            {
                if (t.Name == _onDevice)
                {
                    // Set before each run from a device tensor (SetInput); Core's array is not uploaded.
                    _deviceInput = true;
                    return;
                }

                TensorShape shape = Shape(t);
                if (t.Kind == TensorElementKind.Float32)
                {
                    // A batch of fewer rows than Core's capacity array is uploaded from an exact-size copy.
                    _inputs.Add((t, new Tensor<float>(shape, false), null, null, t.IsView ? new float[t.Length] : null));
                }
                else
                {
                    _inputs.Add((t, null, new Tensor<int>(shape, false), new int[t.Length], null));
                }
            }

            public void BindOutput(InferenceTensor t)
            {
                if (t.Name == _onDevice) _deviceOutput = true;
                else _outputs.Add(t);
            }

            public void SetInput(IDeviceTensor tensor)
            {
                if (!_deviceInput) throw new InvalidOperationException("this binding has no device input");
                _input = tensor as DeviceTensor ?? throw new ArgumentException("expected a device tensor of a Sentis backend", nameof(tensor));
            }

            public IDeviceTensor TakeOutput()
            {
                if (!_deviceOutput) throw new InvalidOperationException("this binding has no device output");
                if (_scheduled || _output == null) throw new InvalidOperationException("no completed run whose device output was not taken");
                DeviceTensor output = _output;
                _output = null;
                return output;
            }

            // Shown in the Profiler's CPU timeline on whichever thread decodes (main or worker): a blocking run,
            // and the scheduling of an asynchronous one (its readback completes in TryComplete).
            private static readonly ProfilerMarker s_Run = new ProfilerMarker("DeltaInterpolator.Sentis.Run");
            private static readonly ProfilerMarker s_Schedule = new ProfilerMarker("DeltaInterpolator.Sentis.Schedule");

            public void Run()
            {
                using (s_Run.Auto())
                {
                    Start();
                    Worker worker = _owner._worker;
                    foreach (InferenceTensor t in _outputs)
                    {
                        Read(worker.PeekOutput(t.Name), t);
                    }
                }
            }

            public void Schedule()
            {
                using var scope = s_Schedule.Auto();
                Start();
                Worker worker = _owner._worker;
                for (int i = 0; i < _outputs.Count; i++)
                {
                    // The binding's own copy (made once, reused): the worker's output is replaced by its next Schedule.
                    if (_copies.Count <= i) _copies.Add(null);
                    Tensor copy = CopyOutput(worker, _outputs[i].Name, _copies[i]);
                    _copies[i] = copy;
                    copy.ReadbackRequest();
                }

                // Sentis CPU schedules Burst jobs (the run, then the copies) into the job system's batch, which starts them only
                // when flushed: flush now so they start at once on the worker threads, rather than at the next poll of their fence
                // (JobHandle.IsCompleted flushes too, unity:Runtime/Jobs/ScriptBindings/JobHandle.bindings.cs), a frame later in a game.
                if (_owner.BackendType == BackendType.CPU) JobHandle.ScheduleBatchedJobs();
                _scheduled = true;
            }

            public bool TryComplete()
            {
                if (!_scheduled) throw new InvalidOperationException("TryComplete without Schedule");
                for (int i = 0; i < _outputs.Count; i++)
                {
                    if (!_copies[i]!.IsReadbackRequestDone()) return false;
                }

                _scheduled = false;
                for (int i = 0; i < _outputs.Count; i++) Read(_copies[i]!, _outputs[i]);
                return true;
            }

#nullable disable
            // Worker.CopyOutput allocates the copy when given null and reuses (reshapes) a given one.
            private static Tensor CopyOutput(Worker worker, string name, Tensor reuse)
            {
                worker.CopyOutput(name, ref reuse);
                return reuse;
            }
#nullable enable

            private void Start()
            {
                if (_disposed) throw new ObjectDisposedException(nameof(IInferenceBinding));
                Worker worker = _owner._worker;
                foreach (var input in _inputs)
                {
                    if (input.Floats != null)
                    {
                        float[] source = input.Core.Floats!;
                        if (input.Staging != null)
                        {
                            Array.Copy(source, input.Staging, input.Staging.Length);
                            source = input.Staging;
                        }

                        input.Floats.Upload(source);
                        worker.SetInput(input.Core.Name, input.Floats);
                    }
                    else
                    {
                        long[] longs = input.Core.Longs!;
                        int[] ints = input.Scratch!;
                        for (int i = 0; i < ints.Length; i++) ints[i] = checked((int)longs[i]);
                        input.Ints!.Upload(ints);
                        worker.SetInput(input.Core.Name, input.Ints);
                    }
                }

                if (_deviceInput)
                {
                    Tensor memory = _input?.Tensor ?? throw new InvalidOperationException($"{_owner.Description.Source}: no device tensor set for input '{_onDevice}' (SetInput), or it was released");
                    worker.SetInput(_onDevice!, memory);
                }

                worker.Schedule();
                if (_deviceOutput)
                {
                    // Copied on the device at once: it stays there for Core's handle, past the worker's next run.
                    _output?.Dispose();
                    _output = new DeviceTensor(CopyOutput(worker, _onDevice!, null));
                }
            }

            private void Read(Tensor output, InferenceTensor target)
            {
                string source = _owner.Description.Source;
                if (output.shape.length != target.Length)
                {
                    throw new InvalidOperationException($"{source}: Sentis output '{target.Name}' has shape {output.shape}, expected [{string.Join(", ", target.Shape)}]");
                }

                bool cpu = _owner.BackendType == BackendType.CPU;
                if (target.Kind == TensorElementKind.Float32)
                {
                    if (!(output is Tensor<float> floats))
                    {
                        throw new InvalidOperationException($"{source}: Sentis output '{target.Name}' is {output.dataType}, expected Float");
                    }

                    float[] dst = target.Floats!;
                    if (cpu)
                    {
                        floats.CompleteAllPendingOperations();
                        floats.AsReadOnlySpan().CopyTo(new Span<float>(dst, 0, target.Length));
                    }
                    else
                    {
                        Array.Copy(floats.DownloadToArray(), dst, target.Length);
                    }
                }
                else
                {
                    if (!(output is Tensor<int> ints))
                    {
                        throw new InvalidOperationException($"{source}: Sentis output '{target.Name}' is {output.dataType}, expected Int (ONNX int64)");
                    }

                    long[] dst = target.Longs!;
                    if (cpu)
                    {
                        ints.CompleteAllPendingOperations();
                        ReadOnlySpan<int> src = ints.AsReadOnlySpan();
                        for (int i = 0; i < target.Length; i++) dst[i] = src[i];
                    }
                    else
                    {
                        int[] src = ints.DownloadToArray();
                        for (int i = 0; i < target.Length; i++) dst[i] = src[i];
                    }
                }
            }

            public void Dispose()
            {
                if (_disposed) return;
                _disposed = true;
                foreach (var input in _inputs)
                {
                    input.Floats?.Dispose();
                    input.Ints?.Dispose();
                }

                _inputs.Clear();
                foreach (Tensor? copy in _copies) copy?.Dispose();
                _copies.Clear();
                _output?.Dispose();
                _output = null;
                _input = null;
                _owner._bindings.Remove(this);
            }
        }
    }
}
