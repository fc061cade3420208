#nullable enable
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using Unity.InferenceEngine;
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
    /// (<c>MainThreadDecoder</c>) schedules a run in one frame (<c>Worker.Schedule</c>, then
    /// <c>Tensor.ReadbackRequest</c> on each output) and collects it in a later frame once
    /// <c>IsReadbackRequestDone</c>, so the main thread never waits for the Burst jobs or the GPU;
    /// <see cref="IInferenceBinding.Run"/> still runs and reads back at once. Not thread-safe:
    /// use a backend from the thread that created it (Unity's main thread for GPU backends).</para>
    /// </remarks>
    public sealed class SentisBackend : IInferenceBackend
    {
        private readonly Worker _worker;
        private readonly List<Binding> _bindings = new List<Binding>();
        private bool _disposed;

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
            if (_disposed) throw new ObjectDisposedException(nameof(SentisBackend));
            Binding binding = BindingTargets.Fill(new Binding(this), Description, inputs, outputs);
            _bindings.Add(binding);
            return binding;
        }

        /// <summary>Disposes every open binding's tensors and the worker.</summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            foreach (Binding b in _bindings.ToArray()) b.Dispose();
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

        private sealed class Binding : IAsyncInferenceBinding, IBindingTarget
        {
            private readonly SentisBackend _owner;
            private readonly List<(InferenceTensor Core, Tensor<float>? Floats, Tensor<int>? Ints, int[]? Scratch, float[]? Staging)> _inputs = new List<(InferenceTensor, Tensor<float>?, Tensor<int>?, int[]?, float[]?)>();
            private readonly List<Tensor> _pending = new List<Tensor>();
            private bool _scheduled;
            private readonly List<InferenceTensor> _outputs = new List<InferenceTensor>();
            private bool _disposed;

            public Binding(SentisBackend owner)
            {
                _owner = owner;
            }

            public void BindInput(InferenceTensor t)
            {
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

            public void BindOutput(InferenceTensor t) => _outputs.Add(t);

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
                _pending.Clear();
                Worker worker = _owner._worker;
                foreach (InferenceTensor t in _outputs)
                {
                    Tensor output = worker.PeekOutput(t.Name);
                    output.ReadbackRequest();
                    _pending.Add(output);
                }

                _scheduled = true;
            }

            public bool TryComplete()
            {
                if (!_scheduled) throw new InvalidOperationException("TryComplete without Schedule");
                foreach (Tensor output in _pending)
                {
                    if (!output.IsReadbackRequestDone()) return false;
                }

                _scheduled = false;
                for (int i = 0; i < _outputs.Count; i++) Read(_pending[i], _outputs[i]);
                return true;
            }

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

                worker.Schedule();
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
                _owner._bindings.Remove(this);
            }
        }
    }
}
