using System;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Fills the three integer inputs: <c>key_frame_indices</c> [K] = 0..P−1, P+n;
    /// <c>query_frame_indices</c> [N] = the missing frames wanted; <c>gap_length</c> [1] = n.
    /// Frame indices are relative to the first past key and must stay ≤ the model's
    /// <see cref="ModelContract.MaxFrameIndex"/>.
    /// </summary>
    public static class FrameIndexBuilder
    {
        /// <summary>Writes 0..P−1 then P+n into <paramref name="keyFrameIndices"/> (length P + 1).</summary>
        public static void KeyFrames(int pastFrames, int missingFrames, Span<long> keyFrameIndices)
        {
            for (int i = 0; i < pastFrames; i++) keyFrameIndices[i] = i;
            keyFrameIndices[pastFrames] = pastFrames + missingFrames;
        }

        /// <summary>Writes P + firstMissing, P + firstMissing + 1, … into <paramref name="queryFrameIndices"/>.</summary>
        /// <param name="pastFrames">P.</param>
        /// <param name="firstMissing">0-based index of the first missing frame wanted (0..n−1).</param>
        /// <param name="queryFrameIndices">Output; its length is the number of frames wanted.</param>
        public static void QueryFrames(int pastFrames, int firstMissing, Span<long> queryFrameIndices)
        {
            for (int i = 0; i < queryFrameIndices.Length; i++) queryFrameIndices[i] = pastFrames + firstMissing + i;
        }

        /// <summary>Writes n into the one-element <paramref name="gapLength"/>.</summary>
        public static void Gap(int missingFrames, Span<long> gapLength) => gapLength[0] = missingFrames;
    }
}
