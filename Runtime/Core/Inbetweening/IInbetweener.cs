namespace DeltaInterpolator.Core.Inbetweening
{
    /// <summary>
    /// Anything that fills the missing frames of a <see cref="Transition"/>: the zero-velocity and
    /// SLERP baselines here, a neural model later. The benchmark evaluates every implementation the
    /// same way, so a new one only has to implement this interface.
    /// </summary>
    public interface IInbetweener
    {
        /// <summary>Stable key for results files, e.g. <c>"slerp"</c> (lower case, no spaces).</summary>
        string Id { get; }

        /// <summary>Name for tables, e.g. <c>"Interp."</c>.</summary>
        string DisplayName { get; }

        /// <summary>
        /// Writes <see cref="Transition.RootPositions"/> and <see cref="Transition.LocalRotations"/> for
        /// every missing frame from the key frames. Must not keep references to the buffers.
        /// </summary>
        void Inbetween(Transition transition);
    }
}
