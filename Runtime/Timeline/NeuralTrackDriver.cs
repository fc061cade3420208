using DeltaInterpolator.Unity;
using UnityEngine.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Timeline
{
    /// <summary>
    /// Hands the director's time to a track's <see cref="NeuralBlendLayer"/> each frame the graph is evaluated (playing,
    /// or previewed and scrubbed in edit mode), lets the character's preview components update their part of an Editor
    /// preview (as Timeline's Animation Track preview callback does), and frees the layer with the graph.
    /// </summary>
    public sealed class NeuralTrackDriver : PlayableBehaviour
    {
        private NeuralBlendLayer? _layer;
        private PlayableDirector? _director;
        private IAnimationWindowPreview[] _previewComponents = new IAnimationWindowPreview[0];

        internal void Bind(NeuralBlendLayer? layer, PlayableDirector? director, IAnimationWindowPreview[] previewComponents)
        {
            _layer = layer;
            _director = director;
            _previewComponents = previewComponents;
        }

        /// <inheritdoc />
        public override void PrepareFrame(Playable playable, FrameData info)
        {
            if (_layer != null && _director != null) _layer.Evaluate(_director.time);
            if (_previewComponents.Length > 0) TrackPreviewComponents.Update(_previewComponents, playable.GetGraph());
        }

        /// <inheritdoc />
        public override void OnPlayableDestroy(Playable playable)
        {
            _layer?.Dispose();
            _layer = null;
        }
    }
}
