using System;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>
    /// Foot locking while a transition plays (the component's setting, run by <see cref="Playback.TransitionPlayer"/>):
    /// every shown pose of the transition, in the order shown, gets its planted feet held and its legs solved
    /// (<see cref="LegPinning"/>), knowing only the poses shown so far, the pose the transition started from and
    /// its target — the run-time counterpart of <see cref="FootLocker"/>, which sees a whole baked clip.
    /// </summary>
    /// <remarks>
    /// <para><b>Ground.</b> At the start pose and at the target the ground is under the lowest foot joint; between
    /// them it moves linearly in time (a transition up a step or a slope ends on the target's ground). Each foot
    /// joint's planted height is the lower of its heights above the ground at the two, kept between 1 % of a leg
    /// below the ground and its flat-footed standing height (<see cref="FootLocker"/>'s rule with two keys).</para>
    /// <para><b>Contacts.</b> A joint planted in the start pose (within <see cref="FootLockSettings.EnterHeight"/> of
    /// its planted height) is held where it stands from the first frame at full weight — the pose shown already has it
    /// there — while the filled motion keeps it below <see cref="FootLockSettings.ExitHeight"/>, within
    /// <see cref="FootLockSettings.HoldDistance"/> of that spot and slower than <see cref="FootLockSettings.HoldSpeed"/>.
    /// If the target plants it within <see cref="FootLockSettings.BridgeDistance"/> of the same spot, the contact
    /// lasts the whole transition, the spot moving linearly to the target's (a foot standing through it), unless the
    /// filled motion lifts it above <see cref="FootLockSettings.StepHeight"/>. Anywhere else a joint becomes planted by
    /// the hysteresis of <see cref="FootLocker.NextPlanted"/> on its height and speed; it is held where it touched
    /// down, or, when the target plants it within the hold distance, on the target's spot (so the transition lands
    /// it where the target has it). Such contacts ease in over <see cref="FootLockSettings.EaseSeconds"/> after
    /// touch-down unless they start where the joint is (nothing later is known yet); every contact eases out over the
    /// same time after it ends, trailing the motion by at most <see cref="FootLockSettings.EaseReach"/> and catching up
    /// by at most that much per ease time.</para>
    /// <para><b>The target is never changed.</b> Over the last <see cref="FootLockSettings.EaseSeconds"/> a hold
    /// within the hold distance of a spot the target plants moves onto that spot; any other hold eases out before
    /// the target time; so the last filled frames meet the target pose. A heel or toe landing on the target's spot
    /// brings the other down on the target's footprint; a held foot's toe never goes more than 1 % of a leg below
    /// its planted height (<see cref="LegPinning"/>'s toe floor); a target beyond the leg's reach
    /// (<see cref="FootLockSettings.MaxReach"/>) releases the joint instead of stretching the leg.</para>
    /// <para><b>Planned.</b> Once the whole span is known (<see cref="PlanSpan"/>: the network's frames all decoded) the
    /// contacts above give way to a bake's plan of the span; see that method.</para>
    /// <para>Times are seconds, so the same settings work at any frame rate. Allocation-free after construction;
    /// one instance per character, not thread-safe.</para>
    /// </remarks>
    public sealed partial class LiveFootLocker
    {
        private const int Channels = FootLocker.ChannelCount;

        private readonly FootRig _rig;
        private readonly FootLockSettings _settings;
        private readonly LegPinning _pinning;
        private readonly double[] _localPositions;
        private readonly int[] _channelJoint = new int[Channels];
        private readonly double[] _maxPlantedHeight = new double[Channels];
        private readonly double[] _legReach = new double[2];
        private readonly double[] _startSpot = new double[3 * Channels];
        private readonly double[] _targetSpot = new double[3 * Channels];
        private readonly bool[] _targetPlants = new bool[Channels];
        private readonly double[] _plantedHeight = new double[Channels];
        private readonly ContactState[] _state = new ContactState[Channels];
        private readonly bool[] _fromStart = new bool[Channels];
        private readonly bool[] _bridged = new bool[Channels];
        private readonly bool[] _onTarget = new bool[Channels];
        private readonly double[] _anchor = new double[3 * Channels];
        private readonly double[] _shownAnchor = new double[3 * Channels];
        private readonly double[] _toeFloor = new double[2];
        private readonly double[] _lastFar = new double[Channels]; // per channel: distance of the motion's joint from its hold, last frame
        private readonly double[] _weight = new double[Channels];
        private readonly double[] _shownWeight = new double[Channels];
        private readonly double[] _previous = new double[3 * Channels];
        private readonly bool[] _predicted = new bool[Channels]; // this pose's predicted contacts, when _hasPrediction
        private bool _hasPrediction;
        private double _groundStart;
        private double _groundTarget;
        private double _startTime;
        private double _targetTime;
        private double _previousTime;
        private bool _active;

        private enum ContactState
        {
            Free,
            Held,
            Releasing,
        }

        /// <summary>Creates a locker for the model's rig (<see cref="FootRig.ForModel"/>); settings default to <see cref="FootLockSettings.ForPlayback"/>.</summary>
        /// <exception cref="ArgumentException">A leg is not a chain thigh → knee → ankle (→ toe).</exception>
        public LiveFootLocker(FootRig rig, FootLockSettings? settings = null)
        {
            _rig = rig ?? throw new ArgumentNullException(nameof(rig));
            _settings = settings ?? FootLockSettings.ForPlayback();
            _settings.Validate();
            _pinning = new LegPinning(rig); // checks the leg chains
            // Spans known whole are planned with the bake's settings: with the frames after a touch-down known, a contact
            // need not be taken early or loosely, as one decided pose by pose must (ForPlayback).
            _planner = new FootLocker(rig);
            Skeleton s = rig.Skeleton;
            FootLocker.ChannelJoints(rig, _channelJoint);
            for (int side = 0; side < 2; side++)
            {
                Leg leg = rig[side];
                _legReach[side] = rig.RestLength(leg.Hip, leg.Knee) + rig.RestLength(leg.Knee, leg.Ankle);
            }

            FootLocker.StandingHeights(rig, _maxPlantedHeight);
            _localPositions = new double[3 * s.JointCount];
            s.OffsetSpan.CopyTo(_localPositions);
        }

        /// <summary>The rig.</summary>
        public FootRig Rig => _rig;

        /// <summary>True between <see cref="Begin"/> and <see cref="End"/>.</summary>
        public bool IsActive => _active;

        /// <summary>After <see cref="LockPose(double, ReadOnlySpan{double}, Span{double})"/>: how strongly (0..1) foot joint <paramref name="channel"/> (0 left ankle, 1 left toe, 2 right ankle, 3 right toe) was held in the pose.</summary>
        public double LockWeight(int channel)
        {
            if ((uint)channel >= Channels) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return _shownWeight[channel];
        }

        /// <summary>True when the last pose locked was given the model's predicted contacts (else its contacts were labelled).</summary>
        public bool LastPosePredicted => _active && _hasPrediction;

        /// <summary>Whether foot joint <paramref name="channel"/> was in a contact (not easing) in the last pose locked.</summary>
        public bool IsPlanted(int channel)
        {
            if ((uint)channel >= Channels) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return _active && _state[channel] == ContactState.Held;
        }

        /// <summary>
        /// A transition starts: the pose it starts from (the pose shown at <paramref name="startTime"/>) and its target
        /// (shown at <paramref name="targetTime"/>), both on the rig's skeleton (root position, joints × 4 local rotations).
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">The target time is not after the start time.</exception>
        public void Begin(ReadOnlySpan<double> startRoot, ReadOnlySpan<double> startRotations, ReadOnlySpan<double> targetRoot, ReadOnlySpan<double> targetRotations, double startTime, double targetTime)
        {
            if (!(targetTime > startTime) || double.IsInfinity(targetTime - startTime)) throw new ArgumentOutOfRangeException(nameof(targetTime), $"target time {targetTime} after start {startTime}; expected a later, finite time");
            double leg = _rig.LegLength;
            FeetOf(startRoot, startRotations, _startSpot);
            FeetOf(targetRoot, targetRotations, _targetSpot);
            _groundStart = LowestFoot(_startSpot);
            _groundTarget = LowestFoot(_targetSpot);
            _startTime = startTime;
            _targetTime = targetTime;
            _previousTime = startTime;
            _planned = _lockedLive = false;
            Array.Copy(_startSpot, _previous, _previous.Length);
            double enter = _settings.EnterHeight * leg;
            for (int c = 0; c < Channels; c++)
            {
                _state[c] = ContactState.Free;
                _weight[c] = 0;
                _shownWeight[c] = 0;
                _fromStart[c] = _bridged[c] = _onTarget[c] = _targetPlants[c] = false;
                if (_channelJoint[c] < 0) continue;
                double riseStart = _startSpot[3 * c + 1] - _groundStart, riseTarget = _targetSpot[3 * c + 1] - _groundTarget;
                _plantedHeight[c] = Math.Max(-0.01 * leg, Math.Min(Math.Min(riseStart, riseTarget), _maxPlantedHeight[c] * leg));
                _targetPlants[c] = riseTarget - _plantedHeight[c] <= enter;
                if (riseStart - _plantedHeight[c] > enter) continue;
                // Planted in the pose shown: held there from the first frame, at full weight (no jump: it is there now).
                _state[c] = ContactState.Held;
                _fromStart[c] = true;
                _weight[c] = 1;
                Array.Copy(_startSpot, 3 * c, _anchor, 3 * c, 3);
                _bridged[c] = _targetPlants[c] && Horizontal(_startSpot, c, _targetSpot, c) <= _settings.BridgeDistance * leg;
                _onTarget[c] = _bridged[c];
            }

            _active = true;
        }

        /// <summary>The transition ended (reached, interrupted or cancelled): later poses are left alone.</summary>
        public void End() => _active = false;

        /// <summary>
        /// Locks the transition's pose shown at <paramref name="time"/> (after the previous call's time): labels each foot
        /// joint's contact, then moves the legs (thigh, knee and ankle rotations) of <paramref name="rotations"/> in place.
        /// Allocation-free.
        /// </summary>
        /// <param name="time">The frame time (seconds, same clock as <see cref="Begin"/>).</param>
        /// <param name="root">The pose's root position.</param>
        /// <param name="rotations">The pose's local rotations (joints × 4), changed in place.</param>
        public void LockPose(double time, ReadOnlySpan<double> root, Span<double> rotations) => LockPose(time, root, rotations, default, 0);

        /// <summary>
        /// <see cref="LockPose(double, ReadOnlySpan{double}, Span{double})"/> with the contacts of the one contact source
        /// (<see cref="FootContacts"/>): a model's predicted probabilities for this pose's four foot joints
        /// (<paramref name="contacts"/>, planted at or above <paramref name="threshold"/>) decide when a joint touches down
        /// and lifts off, instead of the height and speed hysteresis; empty (SLERP, a model without them, a frame not
        /// decoded yet) labels them as before. Where a joint is held, reach and easing are the same. Allocation-free.
        /// </summary>
        /// <exception cref="ArgumentException">Contacts given that are not 4 probabilities, or a threshold not in (0, 1).</exception>
        public void LockPose(double time, ReadOnlySpan<double> root, Span<double> rotations, ReadOnlySpan<float> contacts, double threshold)
        {
            if (!_active) return;
            _hasPrediction = !contacts.IsEmpty;
            if (_hasPrediction)
            {
                if (contacts.Length != Channels) throw new ArgumentException($"{contacts.Length} contact probabilities; expected {Channels} (left ankle, left toe, right ankle, right toe)", nameof(contacts));
                if (!(threshold > 0 && threshold < 1)) throw new ArgumentOutOfRangeException(nameof(threshold), threshold, "expected a probability strictly between 0 and 1");
                for (int c = 0; c < Channels; c++) _predicted[c] = contacts[c] >= threshold;
            }

            double leg = _rig.LegLength;
            double dt = time - _previousTime;
            double u = Math.Max(0, Math.Min(1, (time - _startTime) / (_targetTime - _startTime)));
            double ground = _groundStart + u * (_groundTarget - _groundStart);
            double ease = Math.Max(_settings.EaseSeconds, 1e-9);
            double untilTarget = _targetTime - time;
            root.Slice(0, 3).CopyTo(_localPositions);
            _pinning.ComputeGlobals(_localPositions, rotations);
            double[] g = _pinning.GlobalPositions;
            bool any = false;
            for (int c = 0; c < Channels; c++)
            {
                int joint = _channelJoint[c];
                _shownWeight[c] = 0;
                if (joint < 0) continue;
                var p = Vector3D.Read(g, 3 * joint);
                if (dt > 0)
                {
                    // Contacts move on only with time: a paused game shows the same locked pose every frame.
                    double rise = p.Y - ground - _plantedHeight[c];
                    double speed = HorizontalDistance(p, Vector3D.Read(_previous, 3 * c)) / dt;
                    p.Write(_previous, 3 * c);
                    Update(c, p, rise, speed, u, dt, ease, leg);
                    _lastFar[c] = (Vector3D.Read(_anchor, 3 * c) - p).Length;
                }

                double w = _weight[c];
                Array.Copy(_anchor, 3 * c, _shownAnchor, 3 * c, 3);
                if (w > 0 && !_onTarget[c])
                {
                    double left = SmoothStep(untilTarget / ease);
                    if (_targetPlants[c] && Horizontal(_anchor, c, _targetSpot, c) <= _settings.HoldDistance * leg)
                    {
                        // The target plants it near here: the hold moves onto the target's spot over the last moments.
                        LegPinning.Lerp(Vector3D.Read(_targetSpot, 3 * c), Vector3D.Read(_anchor, 3 * c), left).Write(_shownAnchor, 3 * c);
                    }
                    else
                    {
                        // Elsewhere: let go before the target, which is shown as it is.
                        w = Math.Min(w, left);
                    }
                }

                // Out of the leg's reach: let go (easing out; the IK straightens the leg towards it, never stretches it).
                if (_state[c] == ContactState.Held && Unreachable(c, p)) Release(c);

                _shownWeight[c] = w;
                any |= w > 0;
            }

            if (_planned) any = ShowPlan(time, ground, dt);
            else _lockedLive |= dt > 0;
            _previousTime = Math.Max(time, _previousTime);
            if (!any) return;
            for (int side = 0; side < 2; side++)
            {
                LandWholeFoot(2 * side, 2 * side + 1);
                // No toe of a held foot goes more than 1 % of a leg below its planted height.
                _toeFloor[side] = ground + _plantedHeight[2 * side + 1] - 0.01 * leg;
            }

            _pinning.Pin(_shownWeight, _shownAnchor, _toeFloor, rotations);
        }

        private void Update(int c, Vector3D p, double rise, double speed, double u, double dt, double ease, double leg)
        {
            double step = Math.Max(0, dt) / ease;
            switch (_state[c])
            {
                case ContactState.Held:
                {
                    bool holds;
                    if (_bridged[c])
                    {
                        // A foot standing through the transition: its spot moves from the start's to the target's.
                        LegPinning.Lerp(Vector3D.Read(_startSpot, 3 * c), Vector3D.Read(_targetSpot, 3 * c), u).Write(_anchor, 3 * c);
                        holds = _hasPrediction ? _predicted[c] : rise <= _settings.StepHeight * leg;
                    }
                    else if (_onTarget[c])
                    {
                        // Landing on the target's footprint (the target plants it there): held while the motion is near it.
                        holds = HorizontalDistance(p, Vector3D.Read(_anchor, 3 * c)) <= _settings.HoldDistance * leg;
                    }
                    else
                    {
                        bool near = HorizontalDistance(p, Vector3D.Read(_anchor, 3 * c)) <= _settings.HoldDistance * leg;
                        holds = near && (_hasPrediction ? _predicted[c]
                            : _fromStart[c] ? rise <= _settings.ExitHeight * leg && speed <= _settings.HoldSpeed * leg
                            : FootLocker.NextPlanted(true, rise / leg, speed / leg, _settings));
                    }

                    if (holds)
                    {
                        _weight[c] = Math.Min(1, _weight[c] + step);
                        return;
                    }

                    Release(c);
                    Fade(c, p, step, leg);
                    return;
                }

                case ContactState.Releasing:
                    // Planted again near the spot it is leaving (a flicker on the thresholds): the same contact goes on.
                    // A contact elsewhere waits until this one has eased out, so the joint moves from spot to spot.
                    if (TouchesDown(c, rise, speed, leg) && HorizontalDistance(p, Vector3D.Read(_anchor, 3 * c)) <= _settings.BridgeDistance * leg)
                    {
                        _state[c] = ContactState.Held;
                        _weight[c] = Math.Min(1, _weight[c] + step);
                        return;
                    }

                    Fade(c, p, step, leg);
                    return;

                default:
                    // Held where it touched down: at full weight at once (it is there now), unless the foot's other joint is
                    // held (the two then share the foot's line, which moves it) or it lands on the target's spot: eased in.
                    if (TryTouchDown(c, p, rise, speed, leg)) _weight[c] = _onTarget[c] || _weight[c ^ 1] > 0 ? Math.Min(1, step) : 1;
                    return;
            }
        }

        /// <summary>A free joint that the hysteresis plants: held where it touched down, or on the target's spot when that is near.</summary>
        private bool TryTouchDown(int c, Vector3D p, double rise, double speed, double leg)
        {
            if (!TouchesDown(c, rise, speed, leg)) return false;
            _state[c] = ContactState.Held;
            _fromStart[c] = false;
            _bridged[c] = false;
            _onTarget[c] = _targetPlants[c] && Horizontal(_previous, c, _targetSpot, c) <= _settings.HoldDistance * leg;
            if (_onTarget[c])
            {
                Array.Copy(_targetSpot, 3 * c, _anchor, 3 * c, 3);
            }
            else
            {
                // Where it touched down, kept within 1 % of a leg of its planted height: it neither sinks nor hovers
                // (it touched down at most EnterHeight above it, so the hold starts within that of where it is).
                double offset = Math.Max(-0.01 * leg, Math.Min(0.01 * leg, rise));
                new Vector3D(p.X, p.Y - rise + offset, p.Z).Write(_anchor, 3 * c);
            }

            return true;
        }

        /// <summary>
        /// A heel or toe landing on the target's spot brings the rest of the foot down on the target's footprint too
        /// (when the target plants it and it is free), easing in from the next frame: pinning one joint of a foot the
        /// filled motion still holds tipped would push the other into the floor.
        /// </summary>
        private void LandWholeFoot(int ankle, int toe)
        {
            if (_channelJoint[toe] < 0) return;
            for (int k = 0; k < 2; k++)
            {
                int held = k == 0 ? ankle : toe, other = k == 0 ? toe : ankle;
                if (!_onTarget[held] || _state[held] != ContactState.Held || !_targetPlants[other] || _state[other] != ContactState.Free) continue;
                _state[other] = ContactState.Held;
                _onTarget[other] = true;
                _fromStart[other] = _bridged[other] = false;
                _weight[other] = 0;
                Array.Copy(_targetSpot, 3 * other, _anchor, 3 * other, 3);
            }
        }

        /// <summary>A free joint touches down: where the model predicts it this pose, else by the hysteresis on height and speed.</summary>
        private bool TouchesDown(int c, double rise, double speed, double leg) =>
            _hasPrediction ? _predicted[c] : FootLocker.NextPlanted(false, rise / leg, speed / leg, _settings);

        private void Release(int c)
        {
            _state[c] = ContactState.Releasing;
            _bridged[c] = false;
            _onTarget[c] = false;
        }

        /// <summary>
        /// Eases a released joint out: how far it trails the motion (weight × distance from its hold) shrinks by at most
        /// <see cref="FootLockSettings.EaseReach"/> per ease time (its whole reach over the ease), and is never more than
        /// that reach (a swinging foot is not dragged back). Measured as a distance, not a weight, so that a joint the
        /// motion carries away fast catches up smoothly instead of jumping by the weight's step times the distance.
        /// Without a reach, by time alone.
        /// </summary>
        private void Fade(int c, Vector3D p, double step, double leg)
        {
            double far = (Vector3D.Read(_anchor, 3 * c) - p).Length, reach = _settings.EaseReach * leg;
            double w = Math.Max(0, _weight[c] - step);
            if (reach > 0 && far > 1e-9 * leg)
            {
                double trail = Math.Min(reach, _weight[c] * _lastFar[c]) - reach * step;
                w = Math.Max(0, Math.Min(_weight[c], trail / far));
            }

            _weight[c] = w;
            if (w <= 0) _state[c] = ContactState.Free;
        }

        /// <summary>The held joint's target, as an ankle target, lies beyond what the leg may reach from the hip (and farther than the motion already stretches it).</summary>
        private bool Unreachable(int c, Vector3D p)
        {
            int side = c / 2;
            Leg leg = _rig[side];
            double[] g = _pinning.GlobalPositions;
            Vector3D hip = Vector3D.Read(g, 3 * leg.Hip);
            Vector3D ankle = Vector3D.Read(g, 3 * leg.Ankle);
            Vector3D target = Vector3D.Read(_anchor, 3 * c) - (p - ankle);
            double full = TwoBoneIk.MaxExtension * _legReach[side];
            double reach = _settings.MaxReach * _legReach[side];
            double now = (ankle - hip).Length;
            return (target - hip).Length > Math.Max(reach, Math.Min(now + 1e-3 * _rig.LegLength, full));
        }

        private void FeetOf(ReadOnlySpan<double> root, ReadOnlySpan<double> rotations, double[] spots)
        {
            root.Slice(0, 3).CopyTo(_localPositions);
            _pinning.ComputeGlobals(_localPositions, rotations);
            double[] g = _pinning.GlobalPositions;
            for (int c = 0; c < Channels; c++)
            {
                if (_channelJoint[c] >= 0) Array.Copy(g, 3 * _channelJoint[c], spots, 3 * c, 3);
            }
        }

        private double LowestFoot(double[] spots)
        {
            double lowest = double.PositiveInfinity;
            for (int c = 0; c < Channels; c++)
            {
                if (_channelJoint[c] >= 0) lowest = Math.Min(lowest, spots[3 * c + 1]);
            }

            return lowest;
        }

        private static double Horizontal(double[] a, int ca, double[] b, int cb) => HorizontalDistance(Vector3D.Read(a, 3 * ca), Vector3D.Read(b, 3 * cb));

        private static double HorizontalDistance(Vector3D a, Vector3D b)
        {
            double dx = a.X - b.X, dz = a.Z - b.Z;
            return Math.Sqrt(dx * dx + dz * dz);
        }

        private static double SmoothStep(double x)
        {
            if (x <= 0) return 0;
            if (x >= 1) return 1;
            return x * x * (3 - 2 * x);
        }
    }
}
