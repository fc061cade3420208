namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>One bake method's scores against the ground truth: accuracy and foot skating on the rig's skeleton.</summary>
    public sealed class MethodScore
    {
        internal MethodScore(string name, BakeAccuracy accuracy, FootSkating skating)
        {
            Name = name;
            Accuracy = accuracy;
            Skating = skating;
        }

        /// <summary>The method's name (<c>BakeMethod.Name</c>).</summary>
        public string Name { get; }

        /// <summary>Position error, L2Q and L2P over the non-key frames.</summary>
        public BakeAccuracy Accuracy { get; }

        /// <summary>Foot skating where the ground truth's feet are planted.</summary>
        public FootSkating Skating { get; }
    }
}
