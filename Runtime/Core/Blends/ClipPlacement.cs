namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// How a track that places its clips (Timeline's <i>Apply Transform Offsets</i>) places one clip's root motion. What
    /// <see cref="ClipRootPath"/> is made from; built once per graph build.
    /// </summary>
    /// <param name="Offset">The clip's offset on the ground, in the track's space.</param>
    /// <param name="RemoveStartOffset">
    /// Whether the clip's root motion counts from its animation's first frame (<c>AnimationPlayableAsset.removeStartOffset</c>,
    /// Timeline's default).
    /// </param>
    /// <param name="MovesRoot">
    /// Whether the clip moves the root at all: Timeline offsets only a clip that does (<c>AnimationPlayableAsset.ShouldApplyOffset</c>);
    /// one that does not leaves the character at the track's offset, its own offset unused.
    /// </param>
    public sealed record ClipPlacement(RootPlacement Offset, bool RemoveStartOffset, bool MovesRoot);
}
