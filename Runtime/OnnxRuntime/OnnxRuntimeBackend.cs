using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using Microsoft.ML.OnnxRuntime;
using OrtElementType = Microsoft.ML.OnnxRuntime.Tensors.TensorElementType;

namespace DeltaInterpolator.OnnxRuntime
{
    /// <summary>
    /// <see cref="IInferenceBackend"/> on ONNX Runtime (CPU). One instance holds one
    /// <see cref="InferenceSession"/> for one graph file; <see cref="Bind"/> wraps Core's arrays in
    /// <see cref="OrtValue"/>s over pinned memory and an <see cref="OrtIoBinding"/> once, so every
    /// <see cref="IInferenceBinding.Run"/> is a single native call that allocates no managed memory.
    /// </summary>
    /// <remarks>
    /// Thread-safety: ONNX Runtime sessions may run concurrently, and separate bindings of one backend
    /// may run on separate threads; one binding must not run on two threads at once (its tensors are
    /// shared). Dispose bindings before the backend; the <see cref="Inbetweener"/> that owns a backend
    /// does both.
    /// </remarks>
    public sealed class OnnxRuntimeBackend : IInferenceBackend
    {
        private readonly InferenceSession _session;
        private readonly RunOptions _runOptions;
        private readonly OpenBindings<Binding> _bindings = new OpenBindings<Binding>();

        private OnnxRuntimeBackend(InferenceSession session, ModelDescription description)
        {
            _session = session;
            _runOptions = new RunOptions();
            Description = description;
        }

        /// <inheritdoc />
        public ModelDescription Description { get; }

        /// <summary>
        /// Loads one graph file.
        /// </summary>
        /// <param name="path">An <c>.onnx</c> file.</param>
        /// <param name="options">Threads and optimisation; null for the defaults.</param>
        /// <exception cref="ModelContractException">The file is missing or is not an ONNX model ONNX Runtime can load.</exception>
        public static OnnxRuntimeBackend Load(string path, OnnxRuntimeOptions? options = null)
        {
            options ??= new OnnxRuntimeOptions();
            // Checked before ONNX Runtime opens it: a directory, named pipe or device is named as such
            // (a named pipe would block the load forever).
            try
            {
                InputFile.Check(path, "an .onnx file");
            }
            catch (InputPathException e)
            {
                string problem = e.Problem == "no such file" ? "the model file does not exist" : "the model path " + e.Problem;
                throw new ModelContractException(path, problem, "expected the path of an .onnx file exported by `python3 -m deltainterp export`");
            }

            var sessionOptions = new SessionOptions
            {
                IntraOpNumThreads = Math.Max(0, options.IntraOpThreads),
                InterOpNumThreads = 1,
                ExecutionMode = ExecutionMode.ORT_SEQUENTIAL,
                GraphOptimizationLevel = options.OptimizeGraph ? GraphOptimizationLevel.ORT_ENABLE_ALL : GraphOptimizationLevel.ORT_DISABLE_ALL,
                LogSeverityLevel = OrtLoggingLevel.ORT_LOGGING_LEVEL_ERROR,
            };
            if (!options.AllowSpinning)
            {
                sessionOptions.AddSessionConfigEntry("session.intra_op.allow_spinning", "0");
            }

            // One read of the file: ONNX Runtime loads the graph from these bytes and Core reads the
            // contract's metadata from the same bytes, as every backend does (OnnxMetadataReader).
            byte[] bytes = File.ReadAllBytes(path);
            // Before ONNX Runtime sees the graph: an operator outside the contract (a Loop of 10^12 trips) is
            // refused here, never loaded or run by the probe.
            ModelOperators.Check(bytes, path, allowQuantized: true);
            InferenceSession session;
            try
            {
                session = new InferenceSession(bytes, sessionOptions);
            }
            catch (OnnxRuntimeException e)
            {
                throw new ModelContractException(path, "ONNX Runtime cannot load it as an ONNX model (" + FirstLine(e.Message) + ")",
                    "expected an .onnx file exported by `python3 -m deltainterp export`; check the path and export the checkpoint again");
            }
            finally
            {
                sessionOptions.Dispose();
            }

            try
            {
                return new OnnxRuntimeBackend(session, Describe(path, session, OnnxMetadataReader.Read(bytes, path)));
            }
            catch
            {
                session.Dispose();
                throw;
            }
        }

        /// <summary>The ONNX Runtime version in use (e.g. for reports).</summary>
        public static string RuntimeVersion => OrtEnv.Instance().GetVersionString();

        /// <inheritdoc />
        public IInferenceBinding Bind(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs)
        {
            _bindings.RequireOpen(nameof(OnnxRuntimeBackend));
            Binding binding = BindingTargets.Fill(new Binding(this), Description, inputs, outputs);
            _bindings.Add(binding);
            return binding;
        }

        /// <summary>Releases the session and every binding still open.</summary>
        public void Dispose()
        {
            if (!_bindings.Close()) return;
            _runOptions.Dispose();
            _session.Dispose();
        }

        private static ModelDescription Describe(string path, InferenceSession session, IReadOnlyDictionary<string, string> metadata)
        {
            return new ModelDescription(path, Tensors(session.InputMetadata, session.InputNames), Tensors(session.OutputMetadata, session.OutputNames), metadata);
        }

        private static List<TensorDescription> Tensors(IReadOnlyDictionary<string, NodeMetadata> map, IReadOnlyList<string> order)
        {
            var list = new List<TensorDescription>(order.Count);
            foreach (string name in order)
            {
                NodeMetadata m = map[name];
                TensorElementKind kind = TensorElementKind.Other;
                var shape = new long[0];
                if (m.IsTensor)
                {
                    switch (m.ElementDataType)
                    {
                        case OrtElementType.Float: kind = TensorElementKind.Float32; break;
                        case OrtElementType.Int64: kind = TensorElementKind.Int64; break;
                    }

                    int[] dims = m.Dimensions;
                    shape = new long[dims.Length];
                    for (int i = 0; i < dims.Length; i++) shape[i] = dims[i];
                }

                list.Add(new TensorDescription(name, kind, shape));
            }

            return list;
        }

        private static string FirstLine(string message)
        {
            string s = message.Replace('\r', ' ');
            int nl = s.IndexOf('\n');
            return nl < 0 ? s.Trim() : s.Substring(0, nl).Trim();
        }

        private sealed class Binding : IInferenceBinding, IBindingTarget
        {
            private readonly OnnxRuntimeBackend _owner;
            private readonly List<OrtValue> _values = new List<OrtValue>();
            private bool _disposed;

            public Binding(OnnxRuntimeBackend owner)
            {
                _owner = owner;
                Io = owner._session.CreateIoBinding();
            }

            public OrtIoBinding Io { get; }

            public void BindInput(InferenceTensor t) => Io.BindInput(t.Name, Wrap(t));

            public void BindOutput(InferenceTensor t) => Io.BindOutput(t.Name, Wrap(t));

            private OrtValue Wrap(InferenceTensor t)
            {
                // Pins the managed array for the binding's lifetime: ONNX Runtime reads inputs from and
                // writes outputs into Core's own arrays (a batch of fewer rows binds the first Length
                // elements of the capacity array: no copy).
                OrtValue v = t.Kind == TensorElementKind.Float32
                    ? OrtValue.CreateTensorValueFromMemory(OrtMemoryInfo.DefaultInstance, new Memory<float>(t.Floats!, 0, t.Length), t.Shape)
                    : OrtValue.CreateTensorValueFromMemory(OrtMemoryInfo.DefaultInstance, new Memory<long>(t.Longs!, 0, t.Length), t.Shape);
                _values.Add(v);
                return v;
            }

            public void Run()
            {
                if (_disposed) throw new ObjectDisposedException(nameof(IInferenceBinding));
                try
                {
                    _owner._session.RunWithBinding(_owner._runOptions, Io);
                }
                catch (OnnxRuntimeException e)
                {
                    throw new InvalidOperationException($"{_owner.Description.Source}: ONNX Runtime failed: {FirstLine(e.Message)}", e);
                }
            }

            public void Dispose()
            {
                if (_disposed) return;
                _disposed = true;
                Io.Dispose();
                foreach (OrtValue v in _values) v.Dispose();
                _values.Clear();
                _owner._bindings.Remove(this);
            }
        }
    }
}
