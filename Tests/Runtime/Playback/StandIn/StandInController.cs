using System;
using DeltaInterpolator.Core.Playback;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// Stands in for an Animator Controller in Core frame-loop tests: layers of states made of real clips (<see cref="StandInLayer"/>),
    /// a float parameter for 1D blend trees, an upper layer that drives only its mask's bones, and root motion played into the root
    /// bone (the character stays put: the base layer's travel on the ground accumulates in the root bone's position, so states and
    /// crossfades continue from where the character is). What a Unity glue reads off-scene — a state's pose at a time, placed where
    /// the controller's own motion brings the character by then — it answers with <see cref="SampleOffScene"/>.
    /// </summary>
    /// <remarks>A frame allocates nothing (the allocation tests drive it).</remarks>
    public sealed class StandInController : IControllerStates
    {
        private readonly StandInLayer[] _layers;
        private readonly double[] _upper;
        private bool _started;

        /// <summary>Creates a controller of <paramref name="layers"/> (index order; layer 0 is the base layer).</summary>
        public StandInController(params StandInLayer[] layers)
        {
            _layers = layers;
            BoneCount = layers[0].Current.BoneCount;
            _upper = new double[4 * BoneCount];
        }

        /// <summary>Bones per pose.</summary>
        public int BoneCount { get; }

        /// <summary>The 1D blend trees' parameter (0..1).</summary>
        public double Parameter { get; set; }

        /// <summary>The time of the last evaluation.</summary>
        public double Time { get; private set; }

        /// <summary>The root's accumulated travel on the ground (x, z), in the root bone's position.</summary>
        public double TravelX { get; private set; }

        /// <inheritdoc cref="TravelX"/>
        public double TravelZ { get; private set; }

        /// <summary>
        /// Root motion on (Unity: <c>Animator.applyRootMotion</c>): the travel on the ground moves the character, not the root bone,
        /// which stays in place (x = z = 0) in the pose and in off-scene samples, as a Unity rig's root bone does under root motion;
        /// the travel comes out as <see cref="VelocityX"/>, <see cref="VelocityZ"/>.
        /// </summary>
        public bool RootMotion { get; set; }

        /// <summary>The root's travel per second over the last advance (x, z; the character's frame): the root motion the engine applies.</summary>
        public double VelocityX { get; private set; }

        /// <inheritdoc cref="VelocityX"/>
        public double VelocityZ { get; private set; }

        /// <summary>The layers.</summary>
        public StandInLayer Layer(int index) => _layers[index];

        /// <inheritdoc/>
        public int LayerCount => _layers.Length;

        /// <summary>The states each layer can play (set by the test), for <see cref="HasState"/>.</summary>
        public StandInState[] States { get; set; } = Array.Empty<StandInState>();

        /// <inheritdoc/>
        public bool HasState(int layer, int stateHash)
        {
            if (layer < 0 || layer >= _layers.Length) return false;
            return Find(stateHash) != null;
        }

        /// <summary>The state of hash <paramref name="hash"/> among <see cref="States"/>, or null.</summary>
        public StandInState? Find(int hash)
        {
            foreach (StandInState s in States)
            {
                if (s.Hash == hash) return s;
            }

            return null;
        }

        /// <summary>Advances to <paramref name="time"/> and writes the pose: the controller's output this frame (the delegate <see cref="Tests.OnnxRuntime.PlayingCharacter"/> takes).</summary>
        public void Evaluate(double time, double[] root, double[] rotations)
        {
            AdvanceTo(time);
            Pose(root, rotations);
        }

        /// <summary>Advances to <paramref name="time"/> without writing a pose (the glue acts on the controller before this frame's evaluation).</summary>
        public void AdvanceTo(double time)
        {
            if (_started && time > Time) Advance(time - Time);
            _started = true;
            Time = time;
        }

        /// <summary>Writes the pose now (no time passes).</summary>
        public void Pose(Span<double> root, Span<double> rotations)
        {
            _layers[0].Evaluate(Parameter, out double height, rotations);
            root[0] = RootMotion ? 0 : TravelX;
            root[1] = height;
            root[2] = RootMotion ? 0 : TravelZ;
            for (int l = 1; l < _layers.Length; l++)
            {
                bool[]? mask = _layers[l].Mask;
                _layers[l].Evaluate(Parameter, out _, _upper);
                for (int b = 0; b < BoneCount; b++)
                {
                    if (mask == null || mask[b]) new ReadOnlySpan<double>(_upper, 4 * b, 4).CopyTo(rotations.Slice(4 * b, 4));
                }
            }
        }

        /// <summary>The layers as the engine reads them before a frame (the last evaluation's state).</summary>
        public int Read(AnimatorLayerState[] into)
        {
            for (int l = 0; l < _layers.Length; l++) into[l] = _layers[l].Read(Parameter);
            return _layers.Length;
        }

        /// <summary>Puts a layer in a state at a time (Unity: <c>Animator.PlayInFixedTime</c>), effective in this frame's evaluation.</summary>
        public void Play(in StateTarget state)
        {
            StandInState s = Find(state.StateHash) ?? throw new ArgumentException($"no state {state.StateHash}", nameof(state));
            _layers[state.Layer].Play(s, state.Seconds);
        }

        /// <summary>
        /// What the glue reads off-scene: <paramref name="state"/>'s pose at its time, its root placed where the controller's own
        /// motion (the state or crossfade playing now, run on for <paramref name="secondsAhead"/>) brings the character. The
        /// controller itself is left as it was.
        /// </summary>
        public void SampleOffScene(in StateTarget state, double secondsAhead, double[] root, double[] rotations)
        {
            StandInState target = Find(state.StateHash) ?? throw new ArgumentException($"no state {state.StateHash}", nameof(state));
            double x = TravelX, z = TravelZ;
            const double step = 1.0 / 120.0;
            for (double done = 0; done < secondsAhead - 1e-12;)
            {
                double dt = Math.Min(step, secondsAhead - done);
                (double dx, double dz) = AdvanceCopy(dt);
                x += dx;
                z += dz;
                done += dt;
            }

            Restore();
            target.Sample(state.Seconds, Parameter, out double height, rotations, out _, out _);
            // Under root motion the engine reads the pose in place: the root bone relative to the character (the glue cannot run
            // the controller ahead; Core places it, see TransitionCharacter.DeferTransition).
            root[0] = RootMotion ? 0 : x;
            root[1] = height;
            root[2] = RootMotion ? 0 : z;
        }

        private void Advance(double dt)
        {
            (double dx, double dz) = _layers[0].Advance(dt, Parameter);
            for (int l = 1; l < _layers.Length; l++) _layers[l].Advance(dt, Parameter);
            TravelX += dx;
            TravelZ += dz;
            VelocityX = dx / dt;
            VelocityZ = dz / dt;
        }

        // The base layer's travel over dt on a copy of its state machine (saved once, restored by Restore).
        private (double, double) AdvanceCopy(double dt)
        {
            if (!_copying)
            {
                _copying = true;
                _snapshot = _layers[0].Save();
            }

            return _layers[0].Advance(dt, Parameter);
        }

        private void Restore()
        {
            if (_copying) _layers[0].Load(_snapshot);
            _copying = false;
        }

        private bool _copying;
        private StandInLayer.Snapshot _snapshot;
    }
}
