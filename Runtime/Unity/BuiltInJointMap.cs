namespace DeltaInterpolator.Unity
{
    /// <summary>The bone-naming conventions a generic rig may follow (Core's built-in joint maps).</summary>
    public enum BuiltInJointMap
    {
        /// <summary>LaFAN1's (the model's own) joint names: Hips, LeftUpLeg, …, Spine2, LeftToe.</summary>
        Lafan1 = 0,

        /// <summary>The CMU database in the MotionBuilder-friendly BVH conversion: LowerBack, Neck1, LeftToeBase, ….</summary>
        Cmu = 1,

        /// <summary>Mixamo rigs (<c>mixamorig:Hips</c>, …; the namespace prefix is ignored).</summary>
        Mixamo = 2,

        /// <summary>The CMU database in the Daz/Poser conversion: hip, abdomen, chest, lThigh, ….</summary>
        Poser = 3,
    }
}
