using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.OnnxRuntime
{
    /// <summary>Loads an exported model and its lazy graphs on ONNX Runtime into a Core <see cref="Inbetweener"/> (through <see cref="InbetweenerLoader"/>).</summary>
    public static class OnnxRuntimeInbetweener
    {
        /// <summary>
        /// Loads <paramref name="path"/> (<c>NAME.onnx</c>, the whole graph) and, when both exist beside it,
        /// <c>NAME.keys.onnx</c> and <c>NAME.frame.onnx</c> for lazy decoding.
        /// </summary>
        /// <param name="path">The whole graph.</param>
        /// <param name="options">Threads and optimisation (every graph gets the same).</param>
        /// <param name="requireLazy">Fail when the lazy graphs are missing instead of loading without them.</param>
        /// <exception cref="ModelContractException">A file is missing, unreadable or does not fit the contract.</exception>
        public static Inbetweener Load(string path, OnnxRuntimeOptions? options = null, bool requireLazy = false) =>
            InbetweenerLoader.Load(new OnnxModelFiles(path, options), requireLazy ? LazyGraphs.Required : LazyGraphs.IfPresent);

        /// <summary><c>DIR/NAME.onnx</c> → <c>DIR/NAME.{kind}.onnx</c>.</summary>
        public static string LazyPath(string path, string kind) =>
            new OnnxModelFiles(path).PathOf(kind == "keys" ? ModelGraphKind.Keys : kind == "frame" ? ModelGraphKind.Frame : ModelGraphKind.Whole);
    }
}
