using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Element type of a model tensor, as far as the contract cares.</summary>
    public enum TensorElementKind
    {
        /// <summary>Any type the contract does not use (the model will be refused if it matters).</summary>
        Other,
        /// <summary>32-bit float.</summary>
        Float32,
        /// <summary>64-bit signed integer.</summary>
        Int64,
    }

    /// <summary>Name, element type and shape of one graph input or output.</summary>
    public sealed class TensorDescription
    {
        /// <summary>Creates a description.</summary>
        /// <param name="name">Tensor name in the graph.</param>
        /// <param name="kind">Element type.</param>
        /// <param name="shape">Dimensions; −1 for a dynamic (named or unknown) axis.</param>
        public TensorDescription(string name, TensorElementKind kind, IReadOnlyList<long> shape)
        {
            Name = name ?? throw new ArgumentNullException(nameof(name));
            Kind = kind;
            Shape = shape ?? Array.Empty<long>();
        }

        /// <summary>Tensor name in the graph.</summary>
        public string Name { get; }

        /// <summary>Element type.</summary>
        public TensorElementKind Kind { get; }

        /// <summary>Dimensions; −1 for a dynamic axis.</summary>
        public IReadOnlyList<long> Shape { get; }

        /// <inheritdoc />
        public override string ToString() => $"{Name} ({Kind}, [{string.Join(", ", Shape)}])";
    }

    /// <summary>
    /// What an inference backend can tell about a loaded graph without running it: its inputs, outputs
    /// and <c>metadata_props</c>, as plain .NET values so that Core never sees a backend's own types.
    /// <see cref="ModelContract.Read"/> checks it.
    /// </summary>
    public sealed class ModelDescription
    {
        /// <summary>Creates a description.</summary>
        /// <param name="source">The model's file path (or another name), used in every error message.</param>
        /// <param name="inputs">Graph inputs in graph order.</param>
        /// <param name="outputs">Graph outputs in graph order.</param>
        /// <param name="metadata">The model's <c>metadata_props</c> (custom metadata map).</param>
        public ModelDescription(string source, IReadOnlyList<TensorDescription> inputs, IReadOnlyList<TensorDescription> outputs, IReadOnlyDictionary<string, string> metadata)
        {
            Source = source ?? "<model>";
            Inputs = inputs ?? throw new ArgumentNullException(nameof(inputs));
            Outputs = outputs ?? throw new ArgumentNullException(nameof(outputs));
            Metadata = metadata ?? throw new ArgumentNullException(nameof(metadata));
        }

        /// <summary>The model's file path or name.</summary>
        public string Source { get; }

        /// <summary>Graph inputs in graph order.</summary>
        public IReadOnlyList<TensorDescription> Inputs { get; }

        /// <summary>Graph outputs in graph order.</summary>
        public IReadOnlyList<TensorDescription> Outputs { get; }

        /// <summary>The model's <c>metadata_props</c>.</summary>
        public IReadOnlyDictionary<string, string> Metadata { get; }

        /// <summary>The input called <paramref name="name"/>, or null.</summary>
        public TensorDescription? FindInput(string name) => Find(Inputs, name);

        /// <summary>The output called <paramref name="name"/>, or null.</summary>
        public TensorDescription? FindOutput(string name) => Find(Outputs, name);

        /// <summary>Checks that the graph has an input of <paramref name="tensor"/>'s name and element type (what every backend checks when binding).</summary>
        /// <exception cref="ModelContractException">It has none, or one of another type.</exception>
        public void RequireInput(InferenceTensor tensor) => Require(tensor, FindInput(tensor.Name), "input");

        /// <summary>Checks that the graph has an output of <paramref name="tensor"/>'s name and element type.</summary>
        /// <exception cref="ModelContractException">It has none, or one of another type.</exception>
        public void RequireOutput(InferenceTensor tensor) => Require(tensor, FindOutput(tensor.Name), "output");

        private void Require(InferenceTensor t, TensorDescription? d, string what)
        {
            if (d == null)
            {
                throw new ModelContractException(Source, $"the graph has no {what} '{t.Name}'", "expected the tensor names of Documentation~/model-contract.md");
            }

            if (d.Kind != t.Kind)
            {
                throw new ModelContractException(Source, $"{what} '{t.Name}' is {d.Kind}", $"expected {t.Kind}");
            }
        }

        private static TensorDescription? Find(IReadOnlyList<TensorDescription> list, string name)
        {
            for (int i = 0; i < list.Count; i++)
            {
                if (string.Equals(list[i].Name, name, StringComparison.Ordinal)) return list[i];
            }

            return null;
        }
    }
}
