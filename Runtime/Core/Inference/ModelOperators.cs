using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// The ONNX operators a model may contain (the contract's "Operators"), checked on the file's bytes before
    /// any engine loads or runs it: a graph outside them (a <c>Loop</c> of 10^12 trips, an <c>If</c>) is refused
    /// at once instead of hanging the probe run. Mirrors <c>Training/Python~/deltainterp/operators.py</c>
    /// (<c>ALLOWED</c>, <c>FORBIDDEN</c>); a test keeps the two lists equal.
    /// </summary>
    public static class ModelOperators
    {
        /// <summary>Operators both Unity Sentis 2.x and Barracuda import (Python's <c>ALLOWED</c>).</summary>
        public static IReadOnlyCollection<string> Portable => PortableSet;

        private static readonly HashSet<string> PortableSet = new HashSet<string>(StringComparer.Ordinal)
        {
            // shape and indexing
            "Constant", "Reshape", "Shape", "Unsqueeze", "Squeeze", "Flatten", "Concat", "Expand", "Slice",
            "Gather", "Transpose", "Identity", "Cast", "Dropout", "Pad", "OneHot", "TopK", "DepthToSpace",
            "SpaceToDepth",
            // arithmetic and comparison
            "Add", "Sum", "Sub", "Mul", "Div", "Pow", "Min", "Max", "Mean", "Greater", "Less", "Equal", "Or",
            "And", "Not", "Xor",
            // linear algebra, reductions, normalisation layers both import
            "Gemm", "MatMul", "ReduceMax", "ReduceMean", "ReduceMin", "ReduceProd", "ReduceSum",
            "BatchNormalization", "InstanceNormalization",
            // activations
            "Relu", "Softmax", "LogSoftmax", "Tanh", "Sqrt", "Sigmoid", "Elu", "LeakyRelu", "Selu", "PRelu",
            "Exp", "Log", "Reciprocal", "Abs", "Neg", "Ceil", "Floor", "Clip", "Acos", "Acosh", "Asin", "Asinh",
            "Atan", "Atanh", "Cos", "Cosh", "Sin", "Sinh", "Tan",
        };

        /// <summary>
        /// What <c>python3 -m deltainterp quantize</c> adds (both of its forms), for the ONNX Runtime backend only:
        /// Sentis imports none of them.
        /// </summary>
        public static IReadOnlyCollection<string> Quantized => QuantizedSet;

        private static readonly HashSet<string> QuantizedSet = new HashSet<string>(StringComparer.Ordinal)
        {
            "DynamicQuantizeLinear", "MatMulInteger", "com.microsoft::DynamicQuantizeMatMul",
        };

        /// <summary>Operators the design names as out, with why (Python's <c>FORBIDDEN</c>).</summary>
        public static readonly IReadOnlyDictionary<string, string> Forbidden = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            ["LayerNormalization"] = "not imported by Barracuda (write it with ReduceMean/Sub/Mul/Sqrt/Div)",
            ["Attention"] = "fused attention is a contrib op neither importer knows (keep MatMul/Softmax)",
            ["MultiHeadAttention"] = "fused attention is a contrib op neither importer knows (keep MatMul/Softmax)",
            ["ScatterND"] = "not imported by Barracuda (in-place index assignment in forward() produces it)",
            ["If"] = "control flow is not imported by Sentis or Barracuda (avoid data-dependent Python branches)",
            ["Loop"] = "control flow is not imported by Sentis or Barracuda (avoid loops over tensor sizes)",
        };

        /// <summary>
        /// Refuses a model whose graph holds an operator outside <see cref="Portable"/> (and
        /// <see cref="Quantized"/> when <paramref name="allowQuantized"/>), naming the first one (sorted) and how
        /// many there are. Reads the graph's node list only; runs nothing.
        /// </summary>
        /// <param name="model">The whole <c>.onnx</c> file.</param>
        /// <param name="source">The file's path or name, for messages.</param>
        /// <param name="allowQuantized">True on a backend that runs quantized graphs (ONNX Runtime).</param>
        /// <exception cref="ModelContractException">An operator outside the contract, or bytes that are not ONNX.</exception>
        public static void Check(ReadOnlySpan<byte> model, string source, bool allowQuantized)
        {
            var outside = new List<string>();
            foreach (string op in OnnxMetadataReader.ReadOperators(model, source))
            {
                if (!PortableSet.Contains(op) && !(allowQuantized && QuantizedSet.Contains(op))) outside.Add(op);
            }

            if (outside.Count == 0) return;
            string first = outside[0];
            foreach (string op in outside)
            {
                // The design's named refusals say why; report one of those first.
                if (Forbidden.ContainsKey(op))
                {
                    first = op;
                    break;
                }
            }

            string why = Forbidden.TryGetValue(first, out string? reason) ? reason : "not imported by both Sentis 2.x and Barracuda";
            string others = outside.Count > 1 ? $" and {outside.Count - 1} other operator(s)" : "";
            // A name from the file: clipped (the CLI escapes control characters when it prints the line).
            string name = first.Length > 64 ? first.Substring(0, 64) + "…" : first;
            throw new ModelContractException(
                source,
                $"the graph uses the operator {name}{others} outside the model contract, so nothing was run ({name}: {why})",
                "expected only the operators listed in Documentation~/model-contract.md (Operators), as python3 -m deltainterp export writes them");
        }
    }
}
