namespace DeltaInterpolator.Core.Blends
{
    /// <summary>How a blend's or gap's root travels, from how the track's clips carry root motion and place each clip.</summary>
    public enum RootTravelMode
    {
        /// <summary>The clips have no root motion (their hips carry the travel): the root stays, the in-between's hips move within the character.</summary>
        None,

        /// <summary>Each clip continues from where the character stands (Timeline's Apply Scene Offsets): the span travels along the model's own root trajectory.</summary>
        SceneOffset,

        /// <summary>Each clip starts at a placement of its own (Timeline's Apply Transform Offsets): the span travels along the model's root trajectory, bent to land on the second clip's placement.</summary>
        TransformOffset,
    }
}
