namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// Finds where a preview graph plays the keyed clip: the node (Unity's <c>AnimationClipPlayable</c>) below the
    /// preview's input that plays it with a weight above 0 through every mixer on the way. The Animation window plays
    /// its clip at weight 1 under its layer mixer; Timeline plays a track's clips under the track's mixer and gives
    /// the clips it is not at weight 0, so the same search says "this clip plays here now" in both, and the found
    /// node's time is the clip's own time (Timeline's clip-in, speed and offsets already applied).
    /// </summary>
    public static class PreviewGraphSearch
    {
        /// <summary>Deeper than any preview graph (Timeline nests a clip 3–4 levels below its track's mixer).</summary>
        public const int MaxDepth = 32;

        /// <summary>What the search needs of the engine's graph; a struct so that searching allocates nothing.</summary>
        public interface IGraph<TNode>
        {
            /// <summary>Whether <paramref name="node"/> exists (an unconnected port gives an invalid node).</summary>
            bool IsValid(TNode node);

            /// <summary>How many inputs <paramref name="node"/> has.</summary>
            int InputCount(TNode node);

            /// <summary>The node connected to input <paramref name="port"/> of <paramref name="node"/>.</summary>
            TNode Input(TNode node, int port);

            /// <summary>The weight <paramref name="node"/> gives its input <paramref name="port"/>.</summary>
            float InputWeight(TNode node, int port);

            /// <summary>The id of the clip <paramref name="node"/> plays, or 0 when it plays no clip (a mixer, a job).</summary>
            int ClipOf(TNode node);
        }

        /// <summary>The search's answer: whether the clip plays, which clip, at what weight (the product along the way).</summary>
        public readonly struct Shown
        {
            /// <summary>Clip <paramref name="clip"/> found at <paramref name="weight"/>.</summary>
            public Shown(int clip, float weight)
            {
                Clip = clip;
                Weight = weight;
            }

            /// <summary>Whether the keyed clip plays below the input at a weight above 0.</summary>
            public bool Found => Clip != 0 && Weight > 0f;

            /// <summary>The clip found, 0 when none.</summary>
            public int Clip { get; }

            /// <summary>Its weight in the input's pose, the product of the weights from the input down to it.</summary>
            public float Weight { get; }
        }

        /// <summary>
        /// The node below <paramref name="root"/> (itself included) that plays <paramref name="keyedClip"/> at the
        /// highest weight above 0; not found where it plays only at weight 0, below <see cref="MaxDepth"/>, or nowhere.
        /// </summary>
        public static Shown Find<TNode, TGraph>(TNode root, int keyedClip, TGraph graph, out TNode node)
            where TGraph : struct, IGraph<TNode>
        {
            node = default!;
            if (keyedClip == 0) return default;
            Shown best = default;
            Search(root, keyedClip, graph, 1f, 0, ref best, ref node);
            return best;
        }

        private static void Search<TNode, TGraph>(TNode at, int keyedClip, TGraph graph, float weight, int depth, ref Shown best, ref TNode node)
            where TGraph : struct, IGraph<TNode>
        {
            if (depth > MaxDepth || weight <= 0f || !graph.IsValid(at)) return;
            if (graph.ClipOf(at) == keyedClip)
            {
                if (weight > best.Weight)
                {
                    best = new Shown(keyedClip, weight);
                    node = at;
                }

                return;
            }

            int inputs = graph.InputCount(at);
            for (int i = 0; i < inputs; i++)
            {
                Search(graph.Input(at, i), keyedClip, graph, weight * graph.InputWeight(at, i), depth + 1, ref best, ref node);
            }
        }
    }
}
