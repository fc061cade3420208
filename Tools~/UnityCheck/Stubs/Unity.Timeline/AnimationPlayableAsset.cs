using UnityEngine.Playables;

namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/Animation/AnimationPlayableAsset.cs
    public partial class AnimationPlayableAsset : PlayableAsset
    {
        public AnimationClip clip { get => throw null!; set => throw null!; }

        public override Playable CreatePlayable(PlayableGraph graph, GameObject go) => throw null!;
    }
}
