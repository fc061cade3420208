namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/Animation/AnimationTrack.cs
    public enum TrackOffset
    {
        ApplyTransformOffsets,
        ApplySceneOffsets,
        Auto,
    }

    // source: timeline:Runtime/Animation/AnimationTrack.cs
    public partial class AnimationTrack : TrackAsset
    {
        public TimelineClip CreateClip(AnimationClip clip) => throw null!;
    }
}
