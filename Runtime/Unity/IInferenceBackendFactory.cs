using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Creates <see cref="IInferenceBackend"/>s for the graphs of an <see cref="InbetweeningModel"/> on one
    /// inference engine. An engine's assembly (e.g. <c>DeltaInterpolator.Sentis</c>) implements it and
    /// registers it with <see cref="InferenceBackends.Register"/> when it loads, so this assembly depends
    /// on no engine.
    /// </summary>
    public interface IInferenceBackendFactory
    {
        /// <summary>The name settings select it by, e.g. <c>"Sentis"</c>.</summary>
        string Name { get; }

        /// <summary>
        /// True when its backends may run on a thread other than Unity's main thread; then the network
        /// runs on a worker thread (<c>WorkerThreadScheduler</c>), otherwise lazily on the main thread.
        /// </summary>
        bool RunsOffMainThread { get; }

        /// <summary>
        /// Loads one graph of <paramref name="model"/>. The backend's <see cref="IInferenceBackend.Description"/>
        /// must carry the contract in its metadata (<c>deltainterp</c> = <see cref="InbetweeningModel.ContractJson"/>
        /// with <c>graph</c> set to <paramref name="graph"/>'s kind, and <c>contract_version</c>) so that
        /// Core checks every engine the same way.
        /// </summary>
        /// <exception cref="ModelContractException">The graph is missing or cannot be loaded.</exception>
        IInferenceBackend Create(InbetweeningModel model, ModelGraphKind graph);
    }
}
