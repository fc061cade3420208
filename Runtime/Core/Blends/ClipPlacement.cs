namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// How a track that places its clips (Timeline's <i>Apply Transform Offsets</i>) places one clip's root motion: the
    /// clip's offset on the ground, whether its root motion counts from the animation's first frame
    /// (<c>AnimationPlayableAsset.removeStartOffset</c>), and whether the clip moves the root at all (Timeline offsets only
    /// a clip that does, <c>AnimationPlayableAsset.ShouldApplyOffset</c>; one that does not leaves the character at the
    /// track's offset). What <see cref="ClipRootPath"/> is made from.
    /// </summary>
    public readonly struct ClipPlacement
    {
        /// <summary>A clip's placement.</summary>
        public ClipPlacement(RootPlacement offset, bool removeStartOffset, bool movesRoot)
        {
            Offset = offset;
            RemoveStartOffset = removeStartOffset;
            MovesRoot = movesRoot;
        }

        /// <summary>The clip's offset in the track's space.</summary>
        public RootPlacement Offset { get; }

        /// <summary>Whether the clip's root motion counts from its animation's first frame (Timeline's default).</summary>
        public bool RemoveStartOffset { get; }

        /// <summary>Whether the clip moves the root (else it plays at the track's offset, its own offset unused).</summary>
        public bool MovesRoot { get; }
    }
}
