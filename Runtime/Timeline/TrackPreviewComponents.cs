using DeltaInterpolator.Core.Blends;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Timeline
{
    /// <summary>
    /// The bound character's <see cref="IAnimationWindowPreview"/> components (Animation Rigging's <c>RigBuilder</c>, or
    /// any other) in a neural track's Timeline preview, inserted after the track's mix as Timeline's Animation Track
    /// inserts them after its own (<c>AnimationTrack.CreateMixerPlayableGraph</c>, outside Play mode) and updated at
    /// every evaluation as <c>AnimationPreviewUpdateCallback</c> updates them. In Play mode they run their own graphs after
    /// the track's output, so with them in the preview the preview shows what plays. When and in which order: Core's
    /// <see cref="PreviewInsertion{TNode}"/>; this class only touches the graph.
    /// </summary>
    /// <remarks>
    /// The insertion cannot happen while the track builds its mixer (Timeline connects the clips into it and it into
    /// the timeline's playable afterwards); the track calls <see cref="Insert"/> from its <c>outputs</c>, which Timeline
    /// reads right after connecting it, and the mixer is then moved from its parent port to the chain's start.
    /// </remarks>
    internal sealed class TrackPreviewComponents
    {
        private static readonly IAnimationWindowPreview[] s_none = new IAnimationWindowPreview[0];
        private readonly PreviewInsertion<Playable> _insertion = new PreviewInsertion<Playable>(p => p.IsValid());
        private IAnimationWindowPreview[] _components = s_none;

        /// <summary>
        /// The track built <paramref name="mixer"/> for <paramref name="character"/>: outside Play mode in the Editor, the
        /// character's preview components (read now, in component order) will follow it; returns them, for the track's
        /// driver to update each evaluation (none in Play mode or a player).
        /// </summary>
        public IAnimationWindowPreview[] Built(Playable mixer, GameObject? character)
        {
            bool editorPreview = false;
#if UNITY_EDITOR
            editorPreview = !Application.isPlaying && character != null;
#endif
            _components = editorPreview ? character!.GetComponents<IAnimationWindowPreview>() : s_none;
            _insertion.Built(mixer, editorPreview && _components.Length > 0);
            return _components;
        }

        /// <summary>
        /// Once Timeline has connected the built mixer to its parent: the mixer's parent port gets the end of the preview
        /// components' chain instead, the chain starting at the mixer, with the port's weight kept. Nothing otherwise.
        /// </summary>
        public void Insert(Object track)
        {
            if (!_insertion.TryTake(m => m.GetOutputCount() > 0 && m.GetOutput(0).IsValid(), out Playable mixer)) return;
            Playable parent = mixer.GetOutput(0);
            int port = -1;
            for (int i = 0; i < parent.GetInputCount() && port < 0; i++)
            {
                if (parent.GetInput(i).Equals(mixer)) port = i;
            }

            if (port < 0) return;
            PlayableGraph graph = mixer.GetGraph();
            float weight = parent.GetInputWeight(port);
            graph.Disconnect(parent, port);
            Playable end = _insertion.Chain(mixer, _components, (component, input) => component.BuildPreviewGraph(graph, input), component => component.GetType().Name,
                warning => Debug.LogWarning($"{track.name}: {warning}", track));
            graph.Connect(end, 0, parent, port);
            parent.SetInputWeight(port, weight);
        }

        /// <summary>What the Animation Track's preview callback does at each evaluation: each live component updates its part of the graph.</summary>
        public static void Update(IAnimationWindowPreview[] components, PlayableGraph graph)
        {
            for (int i = 0; i < components.Length; i++)
            {
                if (components[i] is Object live && live != null) components[i].UpdatePreviewGraph(graph);
            }
        }
    }
}
