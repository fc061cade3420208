using UnityEngine.Playables;

namespace UnityEngine.Animations
{
    // source: unity:Modules/Animation/Managed/IAnimationWindowPreview.cs
    public interface IAnimationWindowPreview
    {
        void StartPreview();

        void StopPreview();

        void UpdatePreviewGraph(PlayableGraph graph);

        Playable BuildPreviewGraph(PlayableGraph graph, Playable inputPlayable);
    }
}
