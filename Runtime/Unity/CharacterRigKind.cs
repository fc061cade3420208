namespace DeltaInterpolator.Unity
{
    /// <summary>How a <see cref="MotionInbetweener"/> finds the character's bones and its reference pose.</summary>
    public enum CharacterRigKind
    {
        /// <summary>
        /// The bones and names a joint map gives (<see cref="InbetweenerSettings.JointMap"/>, or a JSON map),
        /// found by name under the Animator; the reference pose is <see cref="InbetweenerSettings.ReferencePose"/>.
        /// </summary>
        Generic = 0,

        /// <summary>
        /// The Animator's humanoid avatar: bones from <c>Animator.GetBoneTransform(HumanBodyBones)</c>, the
        /// reference pose the avatar's own T-pose (<c>avatar.humanDescription.skeleton</c>).
        /// </summary>
        Humanoid = 1,

        /// <summary>
        /// <see cref="Humanoid"/> when the Animator has a humanoid avatar (most Unity characters), <see cref="Generic"/>
        /// otherwise; decided when the component starts. The default of new settings.
        /// </summary>
        Automatic = 2,
    }
}
