using System;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>
    /// When a foot counts as planted and how locking eases in and out. Heights are in leg lengths above the
    /// foot joint's planted height (its height above the ground when it stands), speeds in leg lengths per
    /// second, so the same settings fit any character, unit and frame rate.
    /// </summary>
    /// <remarks>
    /// Hysteresis: a foot joint becomes planted when it is below <see cref="EnterHeight"/> and slower than
    /// <see cref="EnterSpeed"/>, and stays planted until it rises above <see cref="ExitHeight"/> or moves faster
    /// than <see cref="ExitSpeed"/>, so that it does not flicker on the thresholds. The speeds are generous
    /// on purpose: the filled motion's stance feet slide (that is what locking removes), its swinging feet
    /// move at several leg lengths per second.
    /// </remarks>
    public sealed class FootLockSettings
    {
        /// <summary>Height (leg lengths above the planted height) under which a foot joint may become planted.</summary>
        public double EnterHeight { get; set; } = 0.02;

        /// <summary>Height (leg lengths above the planted height) above which a planted foot joint is released.</summary>
        public double ExitHeight { get; set; } = 0.06;

        /// <summary>Speed (leg lengths per second) under which a foot joint may become planted.</summary>
        public double EnterSpeed { get; set; } = 0.5;

        /// <summary>Speed (leg lengths per second) above which a planted foot joint is released.</summary>
        public double ExitSpeed { get; set; } = 1.0;

        /// <summary>
        /// How far (leg lengths, horizontally) the filled motion may carry a foot joint from where a key plants it
        /// before the contact ends: past it the foot has stepped away, and it is let go.
        /// </summary>
        public double HoldDistance { get; set; } = 0.3;

        /// <summary>
        /// Speed (leg lengths per second) above which the filled motion ends a key's contact: a joint it moves that
        /// fast has lifted off (or not yet landed). <see cref="double.PositiveInfinity"/> for filled motion whose timing
        /// means nothing (<see cref="ForInterpolation"/>).
        /// </summary>
        public double HoldSpeed { get; set; } = 1.5;

        /// <summary>
        /// While easing in or out, a joint the filled motion has carried this far (leg lengths) from its target is not
        /// pulled at all, nearer ones in proportion, so that a foot swinging away is not dragged back; 0 to ease by
        /// time alone (<see cref="ForInterpolation"/>). Too short, and a foot far from its spot is hardly pulled on the
        /// frame before a contact and fully held on the contact's first frame: it snaps onto the spot. Chosen on the
        /// development files of <c>FootLockDevelopmentMeasureTests</c> (training subjects only; 0, 0.15, 0.3, 0.5 and 1
        /// tried): 0.5 skates 2–3 % less than 0.3 at keys every 15 and 30 model frames with the feet's acceleration no
        /// higher; 0 and 1 skate less still but shake the feet more (dragging a swinging foot back).
        /// </summary>
        public double EaseReach { get; set; } = 0.5;

        /// <summary>
        /// Two keys that plant a foot joint within this distance (leg lengths) of each other make one
        /// contact across their gap (held on the line between the two spots), unless the filled motion lifts the joint
        /// higher than <see cref="StepHeight"/> in between. Farther apart, each key holds it on its own side of the gap.
        /// </summary>
        public double BridgeDistance { get; set; } = 0.01;

        /// <summary>Height (leg lengths) that breaks a bridge between two keys (<see cref="BridgeDistance"/>): a step in place.</summary>
        public double StepHeight { get; set; } = 0.1;

        /// <summary>Seconds over which locking eases in before a contact and out after it (at least one frame).</summary>
        public double EaseSeconds { get; set; } = 0.15;

        /// <summary>Contacts shorter than this many seconds are ignored (a foot brushing the ground).</summary>
        public double MinContactSeconds { get; set; } = 0.05;

        /// <summary>
        /// A planted foot whose target lies farther from the hip than this fraction of thigh + shin is released
        /// (eased out) rather than stretched. 0.998 leaves a knee at least about 7° bent (0.995, before, about 11°): a
        /// stance leg is nearly straight, and on the development files of <c>FootLockDevelopmentMeasureTests</c> (training
        /// subjects only) the longer reach skates 7 % less at keys every 15 model frames (1 % at 30), feet's acceleration
        /// no higher; 1 (a straight knee, whose angle swings with the slightest change of reach) gained only 0.001 more.
        /// </summary>
        public double MaxReach { get; set; } = 0.998;

        /// <summary>
        /// Settings for filled motion that is an interpolation of the keys (SLERP): its feet slide at a steady speed
        /// whatever the truth did, so neither their speed nor their distance from a key's spot says when a foot lifted;
        /// keys' contacts are held as far as <see cref="HoldDistance"/> and eased by time alone.
        /// </summary>
        public static FootLockSettings ForInterpolation() => new FootLockSettings { HoldSpeed = double.PositiveInfinity, EaseReach = 0 };

        /// <summary>
        /// Settings for transitions as they play (<see cref="LiveFootLocker"/>): a network's stance feet sink, rise and
        /// slide a little more than a bake's keys let them, and nothing later is known when a contact starts, so a foot
        /// is taken as planted a little higher and faster than in a bake; a hold ends sooner (HoldDistance) and catches up
        /// with the motion faster (EaseReach, EaseSeconds), since its end is not planned ahead. Chosen on a LaFAN1
        /// subject-1 walk in the frame-loop test with the CMU model of the time (skating of 1 s transitions × 0.58
        /// of unlocked with the bake's settings, × 0.52 with these; 0.5 s ones × 0.99 and × 0.69); with the model
        /// shipped after it, × 0.59 and × 0.81.
        /// </summary>
        public static FootLockSettings ForPlayback() => new FootLockSettings
        {
            EnterHeight = 0.03, ExitHeight = 0.06, EnterSpeed = 1.0, ExitSpeed = 1.5, HoldSpeed = 2.5,
            HoldDistance = 0.15, EaseReach = 0.1, EaseSeconds = 0.1,
        };

        /// <summary>Throws when a value is out of range; called by <see cref="FootLocker"/>.</summary>
        /// <exception cref="ArgumentOutOfRangeException">A threshold is negative, an exit threshold is below its entry, or the reach is not in (0, 1].</exception>
        public void Validate()
        {
            if (!(EnterHeight >= 0) || !(ExitHeight >= EnterHeight)) throw new ArgumentOutOfRangeException(nameof(ExitHeight), $"heights {EnterHeight} (enter) and {ExitHeight} (exit); expected 0 ≤ enter ≤ exit");
            if (!(EnterSpeed >= 0) || !(ExitSpeed >= EnterSpeed)) throw new ArgumentOutOfRangeException(nameof(ExitSpeed), $"speeds {EnterSpeed} (enter) and {ExitSpeed} (exit); expected 0 ≤ enter ≤ exit");
            if (!(HoldDistance >= 0) || double.IsInfinity(HoldDistance)) throw new ArgumentOutOfRangeException(nameof(HoldDistance), $"hold distance {HoldDistance}; expected a non-negative number of leg lengths");
            if (!(BridgeDistance >= 0) || double.IsInfinity(BridgeDistance)) throw new ArgumentOutOfRangeException(nameof(BridgeDistance), $"bridge distance {BridgeDistance}; expected a non-negative number of leg lengths");
            if (!(HoldSpeed >= 0)) throw new ArgumentOutOfRangeException(nameof(HoldSpeed), $"hold speed {HoldSpeed}; expected a non-negative number of leg lengths per second (or infinity)");
            if (!(EaseReach >= 0) || double.IsInfinity(EaseReach)) throw new ArgumentOutOfRangeException(nameof(EaseReach), $"ease reach {EaseReach}; expected a non-negative number of leg lengths (0: off)");
            if (!(StepHeight >= 0) || double.IsInfinity(StepHeight)) throw new ArgumentOutOfRangeException(nameof(StepHeight), $"step height {StepHeight}; expected a non-negative number of leg lengths");
            if (!(EaseSeconds >= 0) || double.IsInfinity(EaseSeconds)) throw new ArgumentOutOfRangeException(nameof(EaseSeconds), $"ease {EaseSeconds} s; expected a non-negative number of seconds");
            if (!(MinContactSeconds >= 0) || double.IsInfinity(MinContactSeconds)) throw new ArgumentOutOfRangeException(nameof(MinContactSeconds), $"minimum contact {MinContactSeconds} s; expected a non-negative number of seconds");
            if (!(MaxReach > 0) || MaxReach > 1) throw new ArgumentOutOfRangeException(nameof(MaxReach), $"reach {MaxReach}; expected a fraction in (0, 1]");
        }
    }
}
