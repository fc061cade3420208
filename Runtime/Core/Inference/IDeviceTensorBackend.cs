using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// A tensor that lives in an inference engine's own memory (a GPU buffer, a native tensor of a CPU
    /// engine): Core holds it by this handle only and never reads it. Made by
    /// <see cref="IDeviceTensorBinding.TakeOutput"/>; the holder disposes it when no run needs it any more.
    /// </summary>
    public interface IDeviceTensor : IDisposable
    {
    }

    /// <summary>
    /// An optional capability of an <see cref="IInferenceBackend"/>: one graph's output stays on the device
    /// and becomes another graph's input there, without a copy through host memory (Sentis on a GPU: the keys
    /// graph's <c>key_memory</c>, bound as the frame graph's input on every frame run). Core's frame
    /// scheduler uses it when both the keys and the frame backend offer it; otherwise it binds every tensor
    /// to host arrays (<see cref="IInferenceBackend.Bind"/>).
    /// </summary>
    public interface IDeviceTensorBackend : IInferenceBackend
    {
        /// <summary>
        /// Binds like <see cref="IInferenceBackend.Bind"/>, except for the one tensor named
        /// <paramref name="onDevice"/> (an input or an output listed among the others, for its name, type and
        /// shape): its Core array is never read or written. As an output, every run leaves it on the device,
        /// for <see cref="IDeviceTensorBinding.TakeOutput"/>; as an input, every run reads the device tensor
        /// given to <see cref="IDeviceTensorBinding.SetInput"/>.
        /// </summary>
        /// <exception cref="ModelContractException">A name or element type does not exist in the graph.</exception>
        IDeviceTensorBinding BindOnDevice(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs, string onDevice);
    }

    /// <summary>
    /// A binding made by <see cref="IDeviceTensorBackend.BindOnDevice"/>. It may also be an
    /// <see cref="IAsyncInferenceBinding"/> (Sentis bindings are).
    /// </summary>
    public interface IDeviceTensorBinding : IInferenceBinding
    {
        /// <summary>
        /// The device input of the next runs (until set again): a tensor of the bound shape, which the caller
        /// keeps alive (undisposed) until those runs have completed. The binding does not own it.
        /// </summary>
        /// <exception cref="InvalidOperationException">The binding has no device input.</exception>
        void SetInput(IDeviceTensor tensor);

        /// <summary>
        /// Hands over the device output of the last run, once it has completed (<see cref="IInferenceBinding.Run"/>
        /// returned, or <see cref="IAsyncInferenceBinding.TryComplete"/> returned true); the caller owns it. Each
        /// run's output is taken once; a later run makes a new one (an untaken output is disposed by the next run or the binding).
        /// </summary>
        /// <exception cref="InvalidOperationException">The binding has no device output, or no completed run whose output was not taken.</exception>
        IDeviceTensor TakeOutput();
    }
}
