namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>
    /// One bake method's scores against the ground truth: accuracy and foot skating on the rig's skeleton. Built by
    /// <see cref="BakeScores.Measure"/>; a record, so two scores compare by value.
    /// </summary>
    /// <param name="Name">The method's name (<c>BakeMethod.Name</c>).</param>
    /// <param name="Accuracy">Position error, L2Q and L2P over the non-key frames.</param>
    /// <param name="Skating">Foot skating where the ground truth's feet are planted.</param>
    public sealed record MethodScore(string Name, BakeAccuracy Accuracy, FootSkating Skating);
}
