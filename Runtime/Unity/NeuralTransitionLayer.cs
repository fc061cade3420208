using System;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Which of an Animator Controller layer's own transitions become neural (<see cref="InbetweenerSettings.NeuralTransitions"/>):
    /// while such a transition plays, the component shows the model's in-between from the character's recent poses to the
    /// next state's pose at the transition's end, so the Animator finishes the transition on exactly that pose.
    /// </summary>
    [Serializable]
    public sealed class NeuralTransitionLayer
    {
        /// <summary>The controller layer (0: the base layer).</summary>
        [Tooltip("The Animator Controller layer whose transitions become neural (0: the base layer).")]
        public int layer = 0;

        /// <summary>Off: the layer keeps its crossfades.</summary>
        [Tooltip("Off: this layer keeps its crossfades.")]
        public bool enabled = true;

        /// <summary>The shortest transition (seconds) made neural; 0: the shortest gap the model was trained on.</summary>
        [Tooltip("Shortest transition (seconds) made neural; shorter ones keep the crossfade. 0: the model's shortest trained gap.")]
        public float minSeconds = 0f;

        /// <summary>The longest transition (seconds) made neural; 0: the longest gap the model was trained on.</summary>
        [Tooltip("Longest transition (seconds) made neural; longer ones keep the crossfade. 0: the model's longest trained gap.")]
        public float maxSeconds = 0f;

        /// <summary>State tags whose transitions into them become neural; empty: every state (unless excluded).</summary>
        [Tooltip("Tags of the states whose incoming transitions become neural; empty: every state.")]
        public string[] includeTags = new string[0];

        /// <summary>State tags whose transitions into them keep the crossfade (wins over <see cref="includeTags"/>).</summary>
        [Tooltip("Tags of the states whose incoming transitions keep the crossfade (wins over Include Tags).")]
        public string[] excludeTags = new string[0];

        /// <summary>
        /// The <c>AvatarMask</c> of a masked layer above this one (e.g. an upper-body layer): bones it drives keep that
        /// layer's pose during a neural transition. Players cannot read a controller's masks, so it is given here.
        /// </summary>
        [Tooltip("The Avatar Mask of a masked layer above this one (e.g. upper body): the bones it drives keep that layer's pose.")]
        public AvatarMask? maskedLayerAbove = null;

        /// <summary>Refuses values no transition could meet, naming the field (<paramref name="name"/> is how the settings call this entry).</summary>
        /// <exception cref="ArgumentOutOfRangeException">A negative layer, a negative or non-finite duration, or a range whose end is below its start.</exception>
        internal void Check(string name)
        {
            if (layer < 0) throw new ArgumentOutOfRangeException(name + "." + nameof(layer), layer, "expected a controller layer index ≥ 0");
            if (!(minSeconds >= 0) || float.IsInfinity(minSeconds)) throw new ArgumentOutOfRangeException(name + "." + nameof(minSeconds), minSeconds, "expected a finite number of seconds ≥ 0 (0: the model's shortest trained gap)");
            if (!(maxSeconds >= 0) || float.IsInfinity(maxSeconds)) throw new ArgumentOutOfRangeException(name + "." + nameof(maxSeconds), maxSeconds, "expected a finite number of seconds ≥ 0 (0: the model's longest trained gap)");
            if (maxSeconds > 0 && maxSeconds < minSeconds) throw new ArgumentOutOfRangeException(name + "." + nameof(maxSeconds), maxSeconds, $"expected at least minSeconds ({minSeconds}) or 0");
        }
    }
}
