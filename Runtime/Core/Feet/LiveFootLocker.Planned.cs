using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>Contacts planned over a transition's whole known span, as a bake plans them, once every frame of it is known.</summary>
    public sealed partial class LiveFootLocker
    {
        private readonly FootLocker _planner;
        private readonly double[] _plannedWeight = new double[Channels];
        private readonly double[] _plannedAnchor = new double[3 * Channels];
        private readonly double[] _plannedShown = new double[Channels]; // the plan's weight as last shown (eased)
        private bool _planned;
        private bool _lockedLive; // a pose of this transition was locked with live contacts before the plan came
        private double _plannedAt;
        private int _planStart;
        private int _planTarget;

        /// <summary>True when the transition's contacts are planned over its whole span (<see cref="PlanSpan"/>) rather than labelled pose by pose.</summary>
        public bool IsPlanned => _active && _planned;

        /// <summary>
        /// Every frame of the transition is known (the network's frames all decoded): labels contacts over the whole span
        /// and plans where each planted joint is held, as a bake does (<see cref="FootLocker.Plan(MotionClip, IReadOnlyList{int}, FootContacts)"/>
        /// with the bake's settings): a touch-down and a lift-off are decided with the frames after them, not only those
        /// before, and each contact is held on one spot. From then on every pose shown takes its weights and spots from
        /// the plan, at its time between the span's frames; a plan that comes after poses were locked pose by pose takes
        /// over from those over <see cref="FootLockSettings.EaseSeconds"/>, so nothing jumps. Until the next
        /// <see cref="Begin"/>. Allocation-free once the locker has planned a span as long.
        /// </summary>
        /// <param name="span">The span on the rig's skeleton: frames before the start pose, the start pose, the frames to show, the target (its last frame).</param>
        /// <param name="keys">The span's key frames (increasing): real poses (the start pose, those before it, the target), never changed, and where the ground is found.</param>
        /// <param name="startKey">The index in <paramref name="keys"/> of the start pose, shown at <see cref="Begin"/>'s start time; the target, the last key, is shown at its target time, the frames between evenly in between.</param>
        /// <param name="contacts">The model's predicted contacts for the span's frames, or null (labelled).</param>
        /// <exception cref="InvalidOperationException">No transition is active.</exception>
        /// <exception cref="ArgumentException">The span is not on the rig's skeleton, its keys are not increasing frames of it, or the start key is not before the last.</exception>
        public void PlanSpan(MotionClip span, IReadOnlyList<int> keys, int startKey, FootContacts? contacts)
        {
            if (!_active) throw new InvalidOperationException("no transition is active: call Begin first");
            if (keys == null) throw new ArgumentNullException(nameof(keys));
            if (startKey < 0 || startKey >= keys.Count - 1) throw new ArgumentOutOfRangeException(nameof(startKey), startKey, $"expected a key before the last (0..{keys.Count - 2})");
            _planner.Plan(span, keys, contacts);
            _planStart = keys[startKey];
            _planTarget = keys[keys.Count - 1];
            _planned = true;
            _plannedAt = _previousTime;
            // The plan's weights start where the start pose has them (a contact through it is held there, where the pose
            // shown has the joint) and, taking over, at what was shown.
            for (int c = 0; c < Channels; c++) _plannedShown[c] = _lockedLive ? _shownWeight[c] : _planner.LockWeight(_planStart, c);
        }

        /// <summary>
        /// The plan's weights and spots at <paramref name="time"/> (between the span's two frames around it) in place of
        /// the live ones, or blended with them while the plan takes over.
        /// </summary>
        private bool ShowPlan(double time, double ground, double dt)
        {
            double leg = _rig.LegLength;
            // A bake's weights jump where a contact meets a key (they never ease across one); shown, they may rise only as
            // fast as an ease, and a hold the target does not have eases out before it, so the start and the end never pop.
            double ease = Math.Max(_planner.Settings.EaseSeconds, 1e-9), rise = Math.Max(0, dt) / ease, left = SmoothStep((_targetTime - time) / ease);
            double x = _planStart + (_planTarget - _planStart) * Math.Max(0, Math.Min(1, (time - _startTime) / (_targetTime - _startTime)));
            int a = Math.Min((int)Math.Floor(x), _planTarget - 1);
            double f = x - a;
            for (int c = 0; c < Channels; c++)
            {
                _plannedWeight[c] = 0;
                if (_channelJoint[c] < 0) continue;
                double wa = _planner.LockWeight(a, c), wb = _planner.LockWeight(a + 1, c);
                double w = Math.Min(wa + f * (wb - wa), _plannedShown[c] + rise);
                if (_planner.LockWeight(_planTarget, c) <= 0) w = Math.Min(w, left);
                _plannedWeight[c] = _plannedShown[c] = w;
                Vector3D spot = wa > 0 && wb > 0 ? LegPinning.Lerp(_planner.HeldAt(a, c), _planner.HeldAt(a + 1, c), f)
                    : wa > 0 ? _planner.HeldAt(a, c) : _planner.HeldAt(a + 1, c);
                // Held no lower than 1 % of a leg below its planted height (the live rule): a spot the plan pulled towards a
                // sinking filled joint, out of the leg's reach, would push the foot into the floor.
                double floor = ground + _plantedHeight[c] - 0.01 * leg;
                if (spot.Y < floor) spot = new Vector3D(spot.X, floor, spot.Z);
                spot.Write(_plannedAnchor, 3 * c);
            }

            // Taking over from live contacts: each joint's pull (weight × way to its spot) moves from the live one to the plan's.
            double s = _lockedLive ? SmoothStep((time - _plannedAt) / Math.Max(_settings.EaseSeconds, 1e-9)) : 1;
            bool any = false;
            for (int c = 0; c < Channels; c++)
            {
                double live = (1 - s) * _shownWeight[c], plan = s * _plannedWeight[c], w = live + plan;
                if (w > 0)
                {
                    Vector3D spot = (live / w) * Vector3D.Read(_shownAnchor, 3 * c) + (plan / w) * Vector3D.Read(_plannedAnchor, 3 * c);
                    spot.Write(_shownAnchor, 3 * c);
                }

                _shownWeight[c] = w;
                any |= w > 0;
            }

            return any;
        }
    }
}
