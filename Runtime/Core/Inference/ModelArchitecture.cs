namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Network size as exported (used by the speed harness to rebuild the same net in PyTorch). Read from the model's
    /// metadata by <see cref="ModelContract"/>; a record, so two models' sizes compare by value.
    /// </summary>
    /// <param name="Width">Token width D.</param>
    /// <param name="Blocks">Number of transformer blocks R.</param>
    /// <param name="Heads">Attention heads per block.</param>
    /// <param name="EmbeddingDim">Size of the frame and gap embeddings.</param>
    /// <param name="EmbeddingSize">Rows of the embedding tables (largest frame index + 1).</param>
    /// <param name="Parameters">Number of trained parameters (0 when the exporter did not say).</param>
    public sealed record ModelArchitecture(int Width, int Blocks, int Heads, int EmbeddingDim, int EmbeddingSize, long Parameters);
}
