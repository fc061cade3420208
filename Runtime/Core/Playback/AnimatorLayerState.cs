namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// One controller layer's state machine as the engine read it before a frame (Unity, per layer: <c>GetCurrentAnimatorStateInfo</c>,
    /// <c>IsInTransition</c>, <c>GetAnimatorTransitionInfo</c>, <c>GetNextAnimatorStateInfo</c>), as plain values for
    /// <see cref="AnimatorTransitions"/>. It describes the controller's last evaluation, i.e. the pose the character showed last.
    /// </summary>
    public struct AnimatorLayerState
    {
        /// <summary>The layer's index in the controller (0: the base layer).</summary>
        public int Layer;

        /// <summary>The current state's hash (Unity: <c>AnimatorStateInfo.fullPathHash</c>) and tag hash (<c>tagHash</c>).</summary>
        public int StateHash, TagHash;

        /// <summary>True while the layer crossfades into <see cref="NextStateHash"/> (Unity: <c>IsInTransition</c>).</summary>
        public bool InTransition;

        /// <summary>The state the transition goes to, and its tag hash; meaningful only <see cref="InTransition"/>.</summary>
        public int NextStateHash, NextTagHash;

        /// <summary>
        /// The transition's identity (Unity: <c>AnimatorTransitionInfo.fullPathHash</c>, or <c>nameHash</c>): a change while in
        /// transition is an interruption, even into the same next state.
        /// </summary>
        public int TransitionId;

        /// <summary>The transition's whole length in seconds (Unity: <c>AnimatorTransitionInfo.duration</c>, in seconds whatever its unit in the controller).</summary>
        public double TransitionSeconds;

        /// <summary>How far the transition is, 0 to 1 (Unity: <c>AnimatorTransitionInfo.normalizedTime</c>).</summary>
        public double TransitionNormalizedTime;

        /// <summary>
        /// The next state's time in seconds when the transition ends (Unity: the next state's time now plus the transition's
        /// remaining seconds × the state's speed): the time at which its pose is the in-between's target.
        /// </summary>
        public double NextStateSecondsAtEnd;

        /// <summary>Seconds until the transition ends: (1 − normalized time) × its length.</summary>
        public double RemainingSeconds => (1 - TransitionNormalizedTime) * TransitionSeconds;
    }
}
