using System;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The one model loader of every front end and engine: opens the whole graph, then both lazy graphs
    /// or neither, and hands them to an <see cref="Inbetweener"/>, which checks the contract of each. A graph
    /// that fails to open or to fit disposes everything opened before it, so a failed load leaks no
    /// engine session.
    /// </summary>
    public static class InbetweenerLoader
    {
        /// <summary>Loads the model <paramref name="graphs"/> describes.</summary>
        /// <param name="graphs">Where the graphs come from (a file set, imported assets).</param>
        /// <param name="lazy">Whether to load the keys and frame graphs.</param>
        /// <exception cref="ModelContractException">A graph is missing (the lazy ones under <see cref="LazyGraphs.Required"/>), cannot be loaded or does not fit the contract.</exception>
        public static Inbetweener Load(IModelGraphs graphs, LazyGraphs lazy = LazyGraphs.IfPresent)
        {
            if (graphs == null) throw new ArgumentNullException(nameof(graphs));
            bool withLazy = lazy != LazyGraphs.None && graphs.HasLazyGraphs;
            if (lazy == LazyGraphs.Required && !withLazy)
            {
                throw new ModelContractException(graphs.Source, "its keys and frame graphs (NAME.keys.onnx, NAME.frame.onnx) are missing",
                    "expected the three graphs of one export (python3 -m deltainterp export writes them together)");
            }

            IInferenceBackend whole = graphs.Open(ModelGraphKind.Whole);
            IInferenceBackend? keys = null;
            IInferenceBackend? frame = null;
            try
            {
                if (withLazy)
                {
                    keys = graphs.Open(ModelGraphKind.Keys);
                    frame = graphs.Open(ModelGraphKind.Frame);
                }
            }
            catch
            {
                whole.Dispose();
                keys?.Dispose();
                throw;
            }

            // From here the Inbetweener owns the backends: it disposes them when a contract check fails.
            return new Inbetweener(whole, keys, frame);
        }
    }
}
