using System;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// One row of a network output: the deltas of one missing frame (a row of the whole graph's n rows, or of a
    /// batched frame run's rows × frames). A view over the run's output tensors, so reading it copies nothing.
    /// An optional output of the contract (one more per-row tensor) becomes one more span here, empty when the
    /// model lacks it, so <see cref="RowDecoder"/> and whoever reads rows see it without another path.
    /// </summary>
    public readonly ref struct OutputRow
    {
        /// <summary>A row from its deltas.</summary>
        /// <param name="rootPositionDelta">The root position delta (3 values).</param>
        /// <param name="rotation6DDelta">The 6D rotation deltas (J × 6 values).</param>
        public OutputRow(ReadOnlySpan<float> rootPositionDelta, ReadOnlySpan<float> rotation6DDelta)
        {
            RootPositionDelta = rootPositionDelta;
            Rotation6DDelta = rotation6DDelta;
        }

        /// <summary>The root position delta (3 values, model units, localized).</summary>
        public ReadOnlySpan<float> RootPositionDelta { get; }

        /// <summary>The 6D rotation deltas (J × 6 values, the contract's 6D convention).</summary>
        public ReadOnlySpan<float> Rotation6DDelta { get; }

        /// <summary>Row <paramref name="row"/> of a run's outputs (<c>root_position_delta</c>, <c>rotation_6d_delta</c>) for <paramref name="joints"/> joints.</summary>
        internal static OutputRow Of(GraphTensors outputs, int row, int joints)
        {
            float[] root = outputs.RootPositionDelta!.Floats!;
            float[] rotation = outputs.Rotation6DDelta!.Floats!;
            int width = 6 * joints;
            return new OutputRow(new ReadOnlySpan<float>(root, 3 * row, 3), new ReadOnlySpan<float>(rotation, row * width, width));
        }
    }
}
