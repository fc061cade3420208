using System;
using System.IO;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The models shipped in the package, and the one rule that finds them (and any other package file, such
    /// as the demo clip): a path relative to the package root, looked up from the working directory upwards,
    /// then from the running tool's folder upwards (a tool built inside a checkout finds the checkout's
    /// files from anywhere).
    /// </summary>
    public static class ShippedModels
    {
        /// <summary>
        /// The default wherever a model is chosen for the user: trained on CMU motion only, so a studio may
        /// ship it in a commercial game (model card: Documentation~/model-card.md).
        /// </summary>
        public const string Default = "Runtime/Models/DeltaInterpolator-CMU.onnx";

        /// <summary>The LaFAN1 model (CC BY-NC-ND 4.0: non-commercial): the official LaFAN1 benchmark's model, and a --model choice.</summary>
        public const string Lafan1 = "Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx";

        /// <summary>
        /// <paramref name="relativePath"/> (e.g. <see cref="Default"/>) found as the class describes, or the
        /// relative path itself when it is nowhere (the caller reports it as missing).
        /// </summary>
        public static string Find(string relativePath)
        {
            if (relativePath == null) throw new ArgumentNullException(nameof(relativePath));
            if (File.Exists(relativePath)) return relativePath;
            foreach (string? start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
            {
                string? dir = start;
                while (!string.IsNullOrEmpty(dir))
                {
                    string candidate = Path.Combine(dir, relativePath);
                    if (File.Exists(candidate)) return candidate;
                    dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar));
                }
            }

            return relativePath;
        }
    }
}
