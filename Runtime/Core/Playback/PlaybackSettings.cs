using System;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>How a <see cref="TransitionPlayer"/> layers transitions over the character's own animation.</summary>
    public sealed class PlaybackSettings
    {
        private double _blendIn = 0.1;
        private double _blendOut = 0.2;

        /// <summary>
        /// Seconds over which the transition's weight rises to 1 after a request (0: at once). The
        /// transition starts from the pose shown, so this only smooths away the controller's own motion.
        /// </summary>
        public double BlendInSeconds
        {
            get => _blendIn;
            set => _blendIn = Check(value, nameof(BlendInSeconds));
        }

        /// <summary>Seconds over which the weight falls back to 0 after the target was shown, returning to the controller's pose (0: at once).</summary>
        public double BlendOutSeconds
        {
            get => _blendOut;
            set => _blendOut = Check(value, nameof(BlendOutSeconds));
        }

        /// <summary>
        /// A level of detail for characters far from the camera: requests play the SLERP of their keys and
        /// never run the network (read at each request).
        /// </summary>
        public bool SlerpOnly { get; set; }

        /// <summary>
        /// Holds planted feet still while a transition plays and solves the legs to them (<see cref="Feet.LiveFootLocker"/>;
        /// read at each request). On by default, as in bakes; a model whose skeleton lacks the model's leg joints
        /// (LaFAN1 names) plays unlocked.
        /// </summary>
        public bool LockFeet { get; set; } = true;

        /// <summary>Past model frames fed to the network (P); 0 takes the largest the model was trained with.</summary>
        public int PastFrames { get; set; }

        private static double Check(double value, string name)
        {
            if (!(value >= 0) || double.IsInfinity(value)) throw new ArgumentOutOfRangeException(name, value, "expected a finite number of seconds ≥ 0");
            return value;
        }
    }
}
