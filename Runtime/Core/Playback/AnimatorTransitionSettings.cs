using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Which of one controller layer's own transitions <see cref="AnimatorTransitions"/> replaces with an in-between. A transition is
    /// replaced when the layer is <see cref="Enabled"/>, its length lies in [<see cref="MinSeconds"/>, <see cref="MaxSeconds"/>] and in the
    /// gaps the model was trained on, and its next state is opted in (<see cref="OptedIn"/>) or else neither opted out
    /// (<see cref="OptedOut"/>) nor filtered out by tag (<see cref="IncludeTags"/>, <see cref="ExcludeTags"/>).
    /// </summary>
    /// <remarks>The engine fills the opt-in and opt-out sets (Unity: from the <c>StateMachineBehaviour</c> on single states); read every frame.</remarks>
    public sealed class LayerTransitionSettings
    {
        private double _min;
        private double _max = double.MaxValue;

        /// <summary>Creates settings for layer <paramref name="layer"/>, enabled, with no duration or tag limits.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="layer"/> is negative.</exception>
        public LayerTransitionSettings(int layer)
        {
            if (layer < 0) throw new ArgumentOutOfRangeException(nameof(layer), layer, "expected a controller layer index ≥ 0");
            Layer = layer;
        }

        /// <summary>The controller layer these settings watch.</summary>
        public int Layer { get; }

        /// <summary>True: the layer's transitions are in-betweened; false: they stay crossfades.</summary>
        public bool Enabled { get; set; } = true;

        /// <summary>The shortest transition (seconds) replaced; shorter ones keep their crossfade.</summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative or not finite (on set).</exception>
        public double MinSeconds
        {
            get => _min;
            set => _min = Check(value, nameof(MinSeconds));
        }

        /// <summary>The longest transition (seconds) replaced; longer ones keep their crossfade (<see cref="double.MaxValue"/>: the model's limit only).</summary>
        /// <exception cref="ArgumentOutOfRangeException">Negative or NaN (on set).</exception>
        public double MaxSeconds
        {
            get => _max;
            set => _max = double.IsPositiveInfinity(value) ? double.MaxValue : Check(value, nameof(MaxSeconds));
        }

        /// <summary>Tag hashes of next states to replace (empty: any tag).</summary>
        public HashSet<int> IncludeTags { get; } = new HashSet<int>();

        /// <summary>Tag hashes of next states never replaced.</summary>
        public HashSet<int> ExcludeTags { get; } = new HashSet<int>();

        /// <summary>State hashes whose incoming transitions are replaced whatever their tag.</summary>
        public HashSet<int> OptedIn { get; } = new HashSet<int>();

        /// <summary>State hashes whose incoming transitions always keep their crossfade.</summary>
        public HashSet<int> OptedOut { get; } = new HashSet<int>();

        /// <summary>True when a transition into a state of hash <paramref name="nextState"/> and tag <paramref name="nextTag"/> may be replaced (not counting its length).</summary>
        public bool Accepts(int nextState, int nextTag)
        {
            if (!Enabled) return false;
            if (OptedIn.Contains(nextState)) return true;
            if (OptedOut.Contains(nextState) || ExcludeTags.Contains(nextTag)) return false;
            return IncludeTags.Count == 0 || IncludeTags.Contains(nextTag);
        }

        private static double Check(double value, string name)
        {
            if (!(value >= 0) || double.IsInfinity(value)) throw new ArgumentOutOfRangeException(name, value, "expected a finite number of seconds ≥ 0");
            return value;
        }
    }
}
