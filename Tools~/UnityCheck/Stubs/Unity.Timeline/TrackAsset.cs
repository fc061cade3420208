using System.Collections.Generic;
using UnityEngine.Playables;

namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/TrackAsset.cs
    public abstract partial class TrackAsset : PlayableAsset
    {
        public IEnumerable<TimelineClip> GetClips() => throw null!;

        public virtual Playable CreateTrackMixer(PlayableGraph graph, GameObject go, int inputCount) => throw null!;

        public sealed override Playable CreatePlayable(PlayableGraph graph, GameObject go) => throw null!;

        public override IEnumerable<PlayableBinding> outputs => throw null!;

        public virtual void GatherProperties(PlayableDirector director, IPropertyCollector driver) => throw null!;

        public TimelineClip CreateClip<T>()
            where T : ScriptableObject, IPlayableAsset => throw null!;
    }
}
