namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Network size as exported (used by the speed harness to rebuild the same net in PyTorch).</summary>
    public sealed class ModelArchitecture
    {
        internal ModelArchitecture(int width, int blocks, int heads, int embeddingDim, int embeddingSize, long parameters)
        {
            Width = width;
            Blocks = blocks;
            Heads = heads;
            EmbeddingDim = embeddingDim;
            EmbeddingSize = embeddingSize;
            Parameters = parameters;
        }

        /// <summary>Token width D.</summary>
        public int Width { get; }
        /// <summary>Number of transformer blocks R.</summary>
        public int Blocks { get; }
        /// <summary>Attention heads per block.</summary>
        public int Heads { get; }
        /// <summary>Size of the frame and gap embeddings.</summary>
        public int EmbeddingDim { get; }
        /// <summary>Rows of the embedding tables (largest frame index + 1).</summary>
        public int EmbeddingSize { get; }
        /// <summary>Number of trained parameters (0 when the exporter did not say).</summary>
        public long Parameters { get; }
    }
}
