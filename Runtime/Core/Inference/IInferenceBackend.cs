using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// One loaded graph on some inference engine (ONNX Runtime in <c>Runtime/OnnxRuntime</c>, Unity
    /// Sentis in <c>Runtime/Sentis</c>). Tensors in, tensors out: no engine type crosses this interface,
    /// so everything before and after the network (localization, features, decoding, FK) lives in Core
    /// and is tested on plain .NET.
    /// </summary>
    /// <remarks>
    /// A backend is created per model file and disposed by its owner (the <see cref="Inbetweener"/>
    /// that was given it). Implementations document their own thread-safety; Core uses one binding from
    /// one thread at a time.
    /// </remarks>
    public interface IInferenceBackend : IDisposable
    {
        /// <summary>Inputs, outputs and metadata of the loaded graph; <see cref="ModelContract.Read"/> checks it.</summary>
        ModelDescription Description { get; }

        /// <summary>
        /// Binds Core-owned tensors once: later <see cref="IInferenceBinding.Run"/> calls read the
        /// current contents of <paramref name="inputs"/> and write <paramref name="outputs"/> in place,
        /// with no allocation. Outputs that are not listed are not computed.
        /// </summary>
        /// <param name="inputs">Every graph input, with the shapes of the request.</param>
        /// <param name="outputs">The outputs wanted, with the shapes the graph will produce for those inputs.</param>
        /// <exception cref="ModelContractException">A name or element type does not exist in the graph.</exception>
        IInferenceBinding Bind(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs);
    }

    /// <summary>A set of bound tensors ready to run; dispose it before its backend.</summary>
    public interface IInferenceBinding : IDisposable
    {
        /// <summary>Runs the graph on the bound inputs and fills the bound outputs.</summary>
        /// <exception cref="InvalidOperationException">The engine failed; the message says why.</exception>
        void Run();
    }

    /// <summary>
    /// A binding whose run can be started in one frame and collected in a later one, so that the thread
    /// that schedules it never waits for the engine (Sentis: <c>Worker.Schedule</c>, then asynchronous
    /// readback of the outputs). Core's frame scheduler uses it when a backend offers it; otherwise it
    /// calls <see cref="IInferenceBinding.Run"/>.
    /// </summary>
    public interface IAsyncInferenceBinding : IInferenceBinding
    {
        /// <summary>Reads the bound inputs now (they may change afterwards) and starts the run.</summary>
        void Schedule();

        /// <summary>
        /// True when the run started by <see cref="Schedule"/> has finished and the bound outputs hold its
        /// results; false while it is still running (call again in a later frame). Never blocks.
        /// </summary>
        /// <exception cref="InvalidOperationException">The engine failed; the message says why.</exception>
        bool TryComplete();
    }
}
