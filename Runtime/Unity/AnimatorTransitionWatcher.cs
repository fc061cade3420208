using System;
using DeltaInterpolator.Core.Playback;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// The Unity side of neural Animator transitions (<see cref="InbetweenerSettings.NeuralTransitions"/>): it turns the
    /// settings into Core's <see cref="LayerTransitionSettings"/> on the character's <see cref="AnimatorTransitions"/>, reads
    /// each watched layer's state machine every frame (<c>GetCurrentAnimatorStateInfo</c>, <c>IsInTransition</c>,
    /// <c>GetAnimatorTransitionInfo</c>, <c>GetNextAnimatorStateInfo</c>) into Core's plain <see cref="AnimatorLayerState"/>,
    /// records the states a <see cref="NeuralTransition"/> behaviour opts in or out, builds the bone mask of a masked layer
    /// above from its <c>AvatarMask</c>, and logs Core's messages (a transition length the model was not trained on keeps
    /// its crossfade: one warning per length). Every decision is Core's.
    /// </summary>
    internal sealed class AnimatorTransitionWatcher
    {
        private readonly Animator _animator;
        private readonly UnityEngine.Object _context;
        private readonly LayerTransitionSettings[] _layers;
        private readonly AnimatorLayerState[] _states;
        private bool _warnedLayer;

        /// <summary>Watches the layers <paramref name="entries"/> name on <paramref name="transitions"/>; refuses entries no controller could meet.</summary>
        /// <exception cref="ArgumentOutOfRangeException">An entry's values are out of range (named by entry and field).</exception>
        public AnimatorTransitionWatcher(Animator animator, NeuralTransitionLayer[] entries, AnimatorTransitions transitions, Transform[] bones, UnityEngine.Object context)
        {
            const string name = "neuralTransitions";
            InbetweenerSettings.CheckNeuralTransitions(entries, name);
            _animator = animator;
            _context = context;
            int watched = 0;
            foreach (NeuralTransitionLayer entry in entries) watched += entry.enabled ? 1 : 0;
            _layers = new LayerTransitionSettings[watched];
            _states = new AnimatorLayerState[watched];
            transitions.Clear();
            int w = 0;
            for (int i = 0; i < entries.Length; i++)
            {
                NeuralTransitionLayer entry = entries[i];
                if (!entry.enabled) continue;
                // A layer beyond the controller's is not refused here: the component may start before the Animator has read its
                // controller (its layer count is 0 until then), and the controller may be assigned or swapped later. Read() says it once.
                var settings = new LayerTransitionSettings(entry.layer)
                {
                    MinSeconds = entry.minSeconds,
                    MaxSeconds = entry.maxSeconds > 0 ? entry.maxSeconds : double.PositiveInfinity,
                };
                foreach (string tag in entry.includeTags ?? new string[0]) if (!string.IsNullOrEmpty(tag)) settings.IncludeTags.Add(Animator.StringToHash(tag));
                foreach (string tag in entry.excludeTags ?? new string[0]) if (!string.IsNullOrEmpty(tag)) settings.ExcludeTags.Add(Animator.StringToHash(tag));
                transitions.Watch(settings);
                _layers[w] = settings;
                _states[w].Layer = entry.layer;
                if (entry.maskedLayerAbove != null) KeptBones = Merge(KeptBones, AvatarMaskBones.Active(entry.maskedLayerAbove, animator, bones));
                w++;
            }

            transitions.Message += Warn;
        }

        /// <summary>True when at least one layer is watched (its transitions may become neural).</summary>
        public bool Watching => _layers.Length > 0;

        /// <summary>One flag per driven bone: true where a masked layer above drives it (it keeps that layer's pose); null: no mask.</summary>
        public bool[]? KeptBones { get; }

        /// <summary>
        /// Each watched layer's state machine as the Animator evaluated it last (the pose shown last), read now.
        /// Allocates nothing: the states are the watcher's own buffer.
        /// </summary>
        public AnimatorLayerState[] Read()
        {
            // A controller assigned or swapped after the build may have fewer layers (none without a controller): those read as
            // not in transition rather than asking the Animator about a layer it lacks (it logs an error each time).
            int layers = _animator.layerCount;
            for (int i = 0; i < _states.Length; i++)
            {
                int layer = _states[i].Layer;
                ref AnimatorLayerState s = ref _states[i];
                if (layer >= layers)
                {
                    s.InTransition = false;
                    if (layers > 0 && !_warnedLayer) WarnLayer(layer, layers);
                    continue;
                }

                AnimatorStateInfo current = _animator.GetCurrentAnimatorStateInfo(layer);
                s.StateHash = current.fullPathHash;
                s.TagHash = current.tagHash;
                s.InTransition = _animator.IsInTransition(layer);
                if (!s.InTransition) continue;
                AnimatorTransitionInfo transition = _animator.GetAnimatorTransitionInfo(layer);
                AnimatorStateInfo next = _animator.GetNextAnimatorStateInfo(layer);
                s.NextStateHash = next.fullPathHash;
                s.NextTagHash = next.tagHash;
                // Interrupting into the same state is a new transition: its identity changes even when the next state does not.
                s.TransitionId = transition.fullPathHash != 0 ? transition.fullPathHash : transition.nameHash;
                // A normalized duration is a fraction of the source state's length (the Animator's transition settings).
                s.TransitionSeconds = transition.durationUnit == DurationUnit.Fixed ? transition.duration : transition.duration * current.length;
                s.TransitionNormalizedTime = transition.normalizedTime;
                // The next state's time in seconds (normalized time × its length, which counts its speed) plus the seconds
                // left of the transition: where PlayInFixedTime puts the state reader for the target pose.
                s.NextStateSecondsAtEnd = next.normalizedTime * next.length + (1 - transition.normalizedTime) * s.TransitionSeconds;
            }

            return _states;
        }

        /// <summary>Records a <see cref="NeuralTransition"/> behaviour's choice for the state <paramref name="stateHash"/> on <paramref name="layer"/>.</summary>
        public void MarkState(int stateHash, int layer, NeuralTransitionMode mode)
        {
            for (int i = 0; i < _layers.Length; i++)
            {
                LayerTransitionSettings settings = _layers[i];
                if (settings.Layer != layer) continue;
                // Set operations on a state already marked allocate nothing; the reader's copy of the controller marks states twice.
                if (mode == NeuralTransitionMode.OptIn)
                {
                    settings.OptedOut.Remove(stateHash);
                    settings.OptedIn.Add(stateHash);
                }
                else
                {
                    settings.OptedIn.Remove(stateHash);
                    settings.OptedOut.Add(stateHash);
                }
            }
        }

        private void WarnLayer(int layer, int layers)
        {
            _warnedLayer = true;
            Debug.LogWarning($"{_context.name}: the settings' Neural Transitions name controller layer {layer}, but the Animator Controller has layers 0–{layers - 1}; that entry's transitions stay crossfades. Expected a layer of the controller (fix Layer in the settings' Neural Transitions)", _context);
        }

        private void Warn(string message) => Debug.LogWarning($"{_context.name}: {message}", _context);

        private static bool[] Merge(bool[]? kept, bool[] active)
        {
            if (kept == null) return active;
            for (int b = 0; b < kept.Length; b++) kept[b] |= active[b];
            return kept;
        }
    }
}
