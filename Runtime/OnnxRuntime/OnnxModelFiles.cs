using System.IO;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.OnnxRuntime
{
    /// <summary>
    /// An exported model's graph files for <see cref="InbetweenerLoader"/>: <c>NAME.onnx</c> (the whole graph)
    /// and, beside it, <c>NAME.keys.onnx</c> and <c>NAME.frame.onnx</c>, each opened on ONNX Runtime.
    /// </summary>
    public sealed class OnnxModelFiles : IModelGraphs
    {
        private readonly OnnxRuntimeOptions? _options;

        /// <param name="path">The whole graph.</param>
        /// <param name="options">Threads and optimisation (every graph gets the same).</param>
        public OnnxModelFiles(string path, OnnxRuntimeOptions? options = null)
        {
            Source = path;
            _options = options;
        }

        /// <inheritdoc />
        public string Source { get; }

        /// <inheritdoc />
        public bool HasLazyGraphs => File.Exists(PathOf(ModelGraphKind.Keys)) && File.Exists(PathOf(ModelGraphKind.Frame));

        /// <summary>The file of one graph: <c>DIR/NAME.onnx</c>, <c>DIR/NAME.keys.onnx</c> or <c>DIR/NAME.frame.onnx</c>.</summary>
        public string PathOf(ModelGraphKind graph)
        {
            if (graph == ModelGraphKind.Whole) return Source;
            string dir = Path.GetDirectoryName(Source) ?? "";
            string name = Path.GetFileNameWithoutExtension(Source);
            return Path.Combine(dir, name + "." + ModelContract.GraphName(graph) + ".onnx");
        }

        /// <inheritdoc />
        public IInferenceBackend Open(ModelGraphKind graph) => OnnxRuntimeBackend.Load(PathOf(graph), _options);
    }
}
