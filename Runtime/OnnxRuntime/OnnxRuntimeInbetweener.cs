using System.IO;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.OnnxRuntime
{
    /// <summary>Loads an exported model and its lazy graphs on ONNX Runtime into a Core <see cref="Inbetweener"/>.</summary>
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
        public static Inbetweener Load(string path, OnnxRuntimeOptions? options = null, bool requireLazy = false)
        {
            string keysPath = LazyPath(path, "keys");
            string framePath = LazyPath(path, "frame");
            bool lazy = File.Exists(keysPath) && File.Exists(framePath);
            if (requireLazy && !lazy)
            {
                throw new ModelContractException(path, $"{Path.GetFileName(keysPath)} or {Path.GetFileName(framePath)} is missing beside it",
                    "expected the three graphs of one export (python3 -m deltainterp export writes them together)");
            }

            OnnxRuntimeBackend whole = OnnxRuntimeBackend.Load(path, options);
            OnnxRuntimeBackend? keys = null;
            OnnxRuntimeBackend? frame = null;
            try
            {
                if (lazy)
                {
                    keys = OnnxRuntimeBackend.Load(keysPath, options);
                    frame = OnnxRuntimeBackend.Load(framePath, options);
                }
            }
            catch
            {
                whole.Dispose();
                keys?.Dispose();
                throw;
            }

            return new Inbetweener(whole, keys, frame);
        }

        /// <summary><c>DIR/NAME.onnx</c> → <c>DIR/NAME.{kind}.onnx</c>.</summary>
        public static string LazyPath(string path, string kind)
        {
            string dir = Path.GetDirectoryName(path) ?? "";
            string name = Path.GetFileNameWithoutExtension(path);
            return Path.Combine(dir, name + "." + kind + ".onnx");
        }
    }
}
