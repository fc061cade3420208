using System;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The graphs of an <see cref="InbetweeningModel"/> asset on one engine, for Core's <see cref="InbetweenerLoader"/>
    /// (the one loader of every front end): the component, the baker window and the Sentis helpers load
    /// models only through <see cref="Load"/>.
    /// </summary>
    public sealed class ModelAssetGraphs : IModelGraphs
    {
        private readonly InbetweeningModel _model;
        private readonly IInferenceBackendFactory _factory;

        /// <summary>The graphs of <paramref name="model"/> opened by <paramref name="factory"/>.</summary>
        public ModelAssetGraphs(InbetweeningModel model, IInferenceBackendFactory factory)
        {
            _model = model != null ? model : throw new ArgumentNullException(nameof(model));
            _factory = factory ?? throw new ArgumentNullException(nameof(factory));
        }

        /// <inheritdoc />
        public string Source => _model.name;

        /// <inheritdoc />
        public bool HasLazyGraphs => _model.HasLazyGraphs;

        /// <inheritdoc />
        public IInferenceBackend Open(ModelGraphKind graph) => _factory.Create(_model, graph);

        /// <summary>Loads <paramref name="model"/> on <paramref name="factory"/>'s engine, named after the asset.</summary>
        /// <exception cref="ModelContractException">A graph is missing, cannot be loaded or does not fit the contract.</exception>
        public static Inbetweener Load(InbetweeningModel model, IInferenceBackendFactory factory, LazyGraphs lazy = LazyGraphs.IfPresent)
        {
            Inbetweener inbetweener = InbetweenerLoader.Load(new ModelAssetGraphs(model, factory), lazy);
            inbetweener.Id = model.name;
            inbetweener.DisplayName = model.name;
            return inbetweener;
        }
    }
}
