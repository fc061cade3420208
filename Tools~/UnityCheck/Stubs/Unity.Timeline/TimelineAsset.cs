using UnityEngine.Playables;

namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/TimelineAsset*.cs
    public partial class TimelineAsset : PlayableAsset
    {
        public T CreateTrack<T>(TrackAsset parent, string trackName)
            where T : TrackAsset, new() => throw null!;

        public override Playable CreatePlayable(PlayableGraph graph, GameObject go) => throw null!;
    }
}
