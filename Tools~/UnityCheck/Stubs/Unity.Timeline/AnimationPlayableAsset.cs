using UnityEngine.Playables;

namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/Animation/AnimationPlayableAsset.cs
    public partial class AnimationPlayableAsset : PlayableAsset
    {
        public enum LoopMode
        {
            UseSourceAsset = 0,
            On = 1,
            Off = 2,
        }

        public LoopMode loop { get => throw null!; set => throw null!; }

        public Vector3 position { get => throw null!; set => throw null!; }

        public Vector3 eulerAngles { get => throw null!; set => throw null!; }

        public bool removeStartOffset { get => throw null!; set => throw null!; }

        public AnimationClip clip { get => throw null!; set => throw null!; }

        public override Playable CreatePlayable(PlayableGraph graph, GameObject go) => throw null!;
    }
}
