namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Where a generic rig's reference pose comes from: the pose in which its bones are compared with the
    /// model's T-pose (each mapped bone must point within 25° of it).
    /// </summary>
    public enum ReferencePoseSource
    {
        /// <summary>
        /// The model's T-pose placed by the bones' local axes: for characters whose bones follow the model's
        /// axes and names (LaFAN1 rigs, whose bind pose is no T-pose).
        /// </summary>
        ModelAxes = 0,

        /// <summary>The pose the bones hold when the component starts (the bind pose of a freshly instantiated character).</summary>
        BindPose = 1,

        /// <summary>The pose a clip shows at a time (<see cref="InbetweenerSettings.ReferenceClip"/>, <see cref="InbetweenerSettings.ReferenceClipTime"/>), e.g. a T-pose frame;
        /// sampled off the scene, onto a hidden copy of the character's transforms: the character's own bones never move for it.</summary>
        ClipFrame = 2,
    }
}
