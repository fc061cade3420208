using DeltaInterpolator.Unity;
using UnityEngine.Playables;

namespace DeltaInterpolator.Timeline
{
    /// <summary>
    /// Hands the director's time to a track's <see cref="NeuralBlendLayer"/> each frame the graph is evaluated (playing,
    /// or previewed and scrubbed in edit mode), and frees the layer with the graph.
    /// </summary>
    public sealed class NeuralTrackDriver : PlayableBehaviour
    {
        private NeuralBlendLayer? _layer;
        private PlayableDirector? _director;

        internal void Bind(NeuralBlendLayer layer, PlayableDirector director)
        {
            _layer = layer;
            _director = director;
        }

        /// <inheritdoc />
        public override void PrepareFrame(Playable playable, FrameData info)
        {
            if (_layer != null && _director != null) _layer.Evaluate(_director.time);
        }

        /// <inheritdoc />
        public override void OnPlayableDestroy(Playable playable)
        {
            _layer?.Dispose();
            _layer = null;
        }
    }
}
