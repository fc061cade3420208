using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Neural Animator transitions with no code: watches the controller layers' state machines (<see cref="AnimatorLayerState"/>,
    /// read by the engine each frame into <see cref="CharacterFrameInput.Layers"/>) and, when a transition the settings accept
    /// starts, in-betweens from the poses shown to the next state's pose at the transition's end, arriving exactly when the
    /// controller finishes the transition. The hand-off is the controller's own: on arrival the layer lets go (weight 0, no
    /// blend-out) and the controller, which played its crossfade underneath all along (its events fire), shows the next state.
    /// </summary>
    /// <remarks>
    /// <para>Owned by a <see cref="TransitionCharacter"/>, which calls it from <see cref="TransitionCharacter.Frame"/>: starting an
    /// in-between defers a hand-off (<see cref="TransitionCharacter.DeferHandOff"/>) and asks the engine, through
    /// <see cref="CharacterFrameOutput.SampleState"/>, for the next state's pose at its time at the transition's end.</para>
    /// <para>An interruption (the layer's transition changes, even into the same state) starts a new in-between from the pose shown.
    /// A transition the settings or the model's trained gaps do not accept keeps its crossfade; one whose length the model was not
    /// trained on says so once per length through <see cref="Message"/> (the engine logs it). An in-between interrupted by a
    /// transition that keeps its crossfade ends at once, handing the character to that crossfade.</para>
    /// <para>Main thread only; a frame without a new transition allocates nothing.</para>
    /// </remarks>
    public sealed class AnimatorTransitions
    {
        private readonly TransitionCharacter _character;
        private readonly List<LayerTransitionSettings> _layers = new List<LayerTransitionSettings>();
        private readonly HashSet<long> _announced = new HashSet<long>();
        // Per watched layer (as _layers), the transition last decided on (replaced or kept): a character's own, as settings may be shared.
        private readonly List<Seen> _seen = new List<Seen>();
        private int _layer = -1;
        private int _requestId;

        internal AnimatorTransitions(TransitionCharacter character)
        {
            _character = character;
        }

        /// <summary>One message per transition length the model was not trained on (that transition keeps its crossfade), for the engine to log.</summary>
        public event Action<string>? Message;

        /// <summary>The watched layers' settings (none: every transition stays a crossfade). Read every frame.</summary>
        public IReadOnlyList<LayerTransitionSettings> Layers => _layers;

        /// <summary>Transitions replaced by an in-between so far (interruptions count again).</summary>
        public int Replaced { get; private set; }

        /// <summary>Transitions that kept their crossfade so far (declined by the settings or the model's trained gaps).</summary>
        public int KeptCrossfades { get; private set; }

        /// <summary>True while an in-between this type started plays or waits for its target.</summary>
        public bool IsInbetweening => _layer >= 0 && IsOurs();

        /// <summary>Watches <paramref name="settings"/>' layer (replacing settings for the same layer).</summary>
        /// <exception cref="ArgumentNullException"><paramref name="settings"/> is null.</exception>
        public void Watch(LayerTransitionSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            for (int i = 0; i < _layers.Count; i++)
            {
                if (_layers[i].Layer != settings.Layer) continue;
                _layers[i] = settings;
                _seen[i] = default;
                return;
            }

            _layers.Add(settings);
            _seen.Add(default);
        }

        /// <summary>Stops watching every layer (transitions stay crossfades; one playing goes on to its target).</summary>
        public void Clear()
        {
            _layers.Clear();
            _seen.Clear();
        }

        /// <summary>The settings of layer <paramref name="layer"/>, or null when it is not watched.</summary>
        public LayerTransitionSettings? For(int layer)
        {
            int i = IndexOf(layer);
            return i < 0 ? null : _layers[i];
        }

        private int IndexOf(int layer)
        {
            for (int i = 0; i < _layers.Count; i++)
            {
                if (_layers[i].Layer == layer) return i;
            }

            return -1;
        }

        // Called by the character's frame after the pose shown is recorded: true (with the state to sample) when an in-between starts.
        internal bool Observe(ReadOnlySpan<AnimatorLayerState> layers, out StateTarget sample)
        {
            sample = default;
            if (_layer >= 0 && !IsOurs()) _layer = -1;
            for (int i = 0; i < layers.Length; i++)
            {
                AnimatorLayerState s = layers[i];
                int watched = IndexOf(s.Layer);
                if (watched < 0) continue;
                LayerTransitionSettings settings = _layers[watched];
                // Each transition is decided once (replaced or kept): it stays seen until its layer leaves transition, even when
                // the in-between arrives a frame before the controller's crossfade ends.
                if (!s.InTransition)
                {
                    _seen[watched] = default;
                    continue;
                }

                Seen seen = _seen[watched];
                if (seen.Valid && seen.Transition == s.TransitionId && seen.Next == s.NextStateHash) continue;
                _seen[watched] = new Seen { Valid = true, Transition = s.TransitionId, Next = s.NextStateHash };
                if (Starts(s, settings, out sample)) return true;
            }

            return false;
        }

        private bool Starts(in AnimatorLayerState s, LayerTransitionSettings settings, out StateTarget sample)
        {
            sample = default;
            double remaining = s.RemainingSeconds;
            bool accepted = settings.Accepts(s.NextStateHash, s.NextTagHash)
                && s.TransitionSeconds >= settings.MinSeconds && s.TransitionSeconds <= settings.MaxSeconds
                && remaining > 0 && double.IsFinite(remaining) && double.IsFinite(s.NextStateSecondsAtEnd) && s.NextStateSecondsAtEnd >= 0
                && Trained(s);
            if (!accepted)
            {
                KeptCrossfades++;
                // The in-between this transition interrupts would fight the crossfade: the crossfade has the character.
                if (_layer == s.Layer && IsOurs()) _character.Cancel();
                if (_layer == s.Layer) _layer = -1;
                return false;
            }

            _requestId = _character.DeferHandOff(remaining);
            _layer = s.Layer;
            Replaced++;
            sample = new StateTarget(s.Layer, s.NextStateHash, s.NextStateSecondsAtEnd);
            return true;
        }

        // The transition's gap lies in the model's trained gaps and within its span; otherwise it keeps the crossfade, said once per length.
        private bool Trained(in AnimatorLayerState s)
        {
            TransitionPlayer player = _character.Player;
            ModelContract c = player.Contract;
            double rate = player.FrameRate;
            long gap = (long)Math.Max(2, Math.Round(s.RemainingSeconds * rate));
            long missing = gap - 1;
            (int nMin, int nMax) = c.TrainingMissingFrames;
            bool trained = !c.HasTrainingRanges || nMax <= 0 || (missing >= nMin && missing <= nMax);
            bool fits = RequestChecks.TooLong(c, player.PastFrames, rate, s.RemainingSeconds) == null;
            if (trained && fits) return true;
            long length = (long)Math.Round(s.TransitionSeconds * rate);
            if (_announced.Add(length))
            {
                double shortest = (nMin + 1) / rate, longest = (nMax + 1) / rate;
                Message?.Invoke($"a {s.TransitionSeconds:0.###} s Animator transition (layer {s.Layer}) keeps the controller's crossfade: the model {c.Name} was trained on transitions of {shortest:0.###}–{longest:0.###} s ({nMin + 1}–{nMax + 1} frames at {rate:0.##} fps); expected a transition length in that range for a neural transition (said once per length)");
            }

            return false;
        }

        private struct Seen
        {
            public bool Valid;
            public int Transition;
            public int Next;
        }

        private bool IsOurs()
        {
            TransitionPlayer p = _character.Player;
            if (p.HasDeferredTransition) return p.DeferredRequestId == _requestId;
            return p.IsPlaying && p.CurrentRequestId == _requestId && !p.HasReachedTarget;
        }
    }
}
