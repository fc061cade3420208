using System;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// A state of the character's Animator Controller at a time in it, as plain values: a hand-off's target (the state's
    /// pose at <see cref="Seconds"/> is the transition's target, and the controller is put in the state on arrival), a
    /// pose the engine is asked to sample off-scene (<see cref="CharacterFrameOutput.SampleState"/>), or the state the
    /// engine is told to play (<see cref="CharacterFrameOutput.PlayState"/>).
    /// </summary>
    /// <remarks>
    /// Unity: <see cref="Layer"/> is the controller layer's index, <see cref="StateHash"/> the state's
    /// <c>Animator.StringToHash</c> of its name or full path, <see cref="Seconds"/> the time in the state as
    /// <c>Animator.PlayInFixedTime</c> takes it (a blend tree's time in its normalized length × its length).
    /// </remarks>
    public readonly struct StateTarget : IEquatable<StateTarget>
    {
        /// <summary>Creates a state target.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="layer"/> is negative, or <paramref name="seconds"/> is negative or not finite.</exception>
        public StateTarget(int layer, int stateHash, double seconds)
        {
            if (layer < 0) throw new ArgumentOutOfRangeException(nameof(layer), layer, "expected a controller layer index ≥ 0");
            if (!(seconds >= 0) || double.IsInfinity(seconds)) throw new ArgumentOutOfRangeException(nameof(seconds), seconds, "expected a finite time in the state, in seconds ≥ 0");
            Layer = layer;
            StateHash = stateHash;
            Seconds = seconds;
        }

        /// <summary>The controller layer (0: the base layer).</summary>
        public int Layer { get; }

        /// <summary>The state's hash (Unity: <c>Animator.StringToHash</c> of its name or full path).</summary>
        public int StateHash { get; }

        /// <summary>The time in the state, in seconds from its start.</summary>
        public double Seconds { get; }

        /// <summary>The same state and layer at another time in it.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="seconds"/> is negative or not finite.</exception>
        public StateTarget At(double seconds) => new StateTarget(Layer, StateHash, seconds);

        /// <inheritdoc/>
        public bool Equals(StateTarget other) => Layer == other.Layer && StateHash == other.StateHash && Seconds.Equals(other.Seconds);

        /// <inheritdoc/>
        public override bool Equals(object? obj) => obj is StateTarget other && Equals(other);

        /// <inheritdoc/>
        public override int GetHashCode() => (Layer * 397) ^ StateHash ^ Seconds.GetHashCode();

        /// <inheritdoc/>
        public override string ToString() => $"state {StateHash} on layer {Layer} at {Seconds:0.###} s";
    }

    /// <summary>
    /// What the engine knows of its Animator Controller's states, for checking a hand-off before it is accepted (Unity:
    /// <c>Animator.layerCount</c> and <c>Animator.HasState</c>). Core never maps a state to its clips; the engine samples it.
    /// </summary>
    public interface IControllerStates
    {
        /// <summary>The controller's layer count.</summary>
        int LayerCount { get; }

        /// <summary>True when layer <paramref name="layer"/> (within <see cref="LayerCount"/>) has a state of hash <paramref name="stateHash"/>.</summary>
        bool HasState(int layer, int stateHash);
    }
}
