using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Feet
{
    /// <summary>
    /// Keeps planted feet still in filled motion: labels each foot joint's contacts (heel = ankle, toe) on
    /// every frame from the key frames and the filled motion, holds a planted joint where it stands, and
    /// solves each leg with analytic two-bone IK (<see cref="TwoBoneIk"/>), easing in before and out after
    /// every contact. Key frames are never changed.
    /// </summary>
    /// <remarks>
    /// <para><b>Ground.</b> At each key the ground is where its lowest foot joint stands — lowest measured along
    /// the slope the neighbouring keys show, so that on a slope a foot swinging behind is not taken for the one
    /// planted ahead; a key whose ground lies above the mean of its neighbours' (a jump, a run's flight) takes that
    /// mean. Under a foot between two keys the ground is on the line through their ground points (slopes and steps
    /// followed key by key), or interpolated in time when those points are close together. Each foot joint's
    /// planted height is its own: the 10th percentile over the keys of its height above the ground, at most its
    /// height in the rig's flat-footed stance plus 1 % of a leg (an ankle stands a few centimetres up, a toe on
    /// the ground), so that a joint the keys never show on the ground is never planted in the air.</para>
    /// <para><b>Contacts from the keys.</b> A key whose joint is within <see cref="FootLockSettings.EnterHeight"/>
    /// of its planted height plants it; the contact carries on into the gaps beside the key while the filled
    /// motion keeps the joint below <see cref="FootLockSettings.ExitHeight"/> and within
    /// <see cref="FootLockSettings.HoldDistance"/> of the key's spot. Two keys that plant it within
    /// <see cref="FootLockSettings.BridgeDistance"/> of each other make one contact across the gap unless the
    /// filled motion lifts it above <see cref="FootLockSettings.StepHeight"/>.</para>
    /// <para><b>Contacts from the filled motion</b> (where no key vouches): hysteresis on height and speed
    /// (<see cref="NextPlanted"/>), at least <see cref="FootLockSettings.MinContactSeconds"/> long. Two different
    /// contacts of a joint are kept at least the ease apart, so that it moves from one spot to the next.</para>
    /// <para><b>Where a planted joint is held.</b> A contact through key frames holds the joint where the keys
    /// have it (linearly from key to key, so it meets every key exactly); any other contact holds it at its mean
    /// position over the contact, within 1 % of a leg length of its planted height above the ground there. On a
    /// contact frame whose target the leg cannot reach (farther from the hip than
    /// <see cref="FootLockSettings.MaxReach"/> of thigh + shin, and farther than the filled motion already
    /// stretches it) the target moves towards the filled joint just into reach: the foot is not stretched, and the
    /// contact is not split (a remainder held on a spot of its own would make the foot jump). Weights ease from 0 to 1 over
    /// <see cref="FootLockSettings.EaseSeconds"/> before a contact and back after it, never across a key, and
    /// fade where the filled joint is far from the target (<see cref="FootLockSettings.EaseReach"/>).</para>
    /// <para><b>Solving a leg</b>: <see cref="LegPinning"/> (shared with the run-time <see cref="LiveFootLocker"/>);
    /// only the thigh, knee and foot rotations of non-key frames change.</para>
    /// <para>Buffers grow to the longest clip seen and are reused; <see cref="LockFrame"/> allocates nothing.
    /// Not thread-safe.</para>
    /// </remarks>
    public sealed partial class FootLocker
    {
        /// <summary>Contact channels: left ankle, left toe, right ankle, right toe (channel = 2 × side + toe).</summary>
        public const int ChannelCount = 4;

        private readonly FootRig _rig;
        private readonly FootLockSettings _settings;
        private readonly int[] _channelJoint = new int[ChannelCount];
        private readonly double[] _maxPlantedHeight = new double[ChannelCount];
        private readonly double[] _plantedHeight = new double[ChannelCount];
        private readonly double[] _thigh = new double[2];
        private readonly LegPinning _pinning;
        private readonly double[] _frameWeights = new double[ChannelCount];
        private readonly double[] _frameTargets = new double[3 * ChannelCount];
        private readonly double[] _shin = new double[2];

        private IReadOnlyList<int>? _keys;
        private int _capacity;
        private int _frames;
        private double[] _feet = Array.Empty<double>();     // channel × capacity × 3: original foot joint positions
        private double[] _hips = Array.Empty<double>();     // side × capacity × 3: original hip (thigh joint) positions
        private double[] _toeVector = Array.Empty<double>(); // side × capacity × 3: toe − ankle, original
        private double[] _ground = Array.Empty<double>();   // channel × capacity: the ground under the joint's (unlocked) position
        private double[] _support = Array.Empty<double>();  // per key: x, z of its lowest foot joint and the ground height there
        private int[] _gap = Array.Empty<int>();            // capacity: index of the key starting the frame's gap
        private int[] _segment = Array.Empty<int>();        // channel × capacity: contact id (0: none; one id per contact)
        private double[] _rise = Array.Empty<double>();     // capacity: the channel being planned, height above its planted height
        private double[] _anchor = Array.Empty<double>();   // channel × capacity × 3
        private double[] _weight = Array.Empty<double>();   // channel × capacity
        private bool[] _isKey = Array.Empty<bool>();        // capacity
        private bool[] _beyondReach = Array.Empty<bool>();  // channel × capacity: contact frames whose spot the leg cannot reach
        private double[] _scratch = Array.Empty<double>();  // 3 × capacity

        /// <summary>Creates a locker for a rig (usually <see cref="FootRig.ForModel"/>).</summary>
        /// <exception cref="ArgumentException">A leg is not a chain thigh → knee → ankle (→ toe).</exception>
        public FootLocker(FootRig rig, FootLockSettings? settings = null)
        {
            _rig = rig ?? throw new ArgumentNullException(nameof(rig));
            _settings = settings ?? new FootLockSettings();
            _settings.Validate();
            _pinning = new LegPinning(rig); // checks the leg chains
            ChannelJoints(rig, _channelJoint);
            StandingHeights(rig, _maxPlantedHeight);
        }

        /// <summary>
        /// A locker for a bake (<see cref="Baking.ClipBaker"/>, <see cref="Workflows.InbetweenBake"/>): a skeleton whose
        /// legs cannot be found or are not joint chains is refused with one message that says how to bake without locking.
        /// </summary>
        /// <param name="rig">Makes the rig (throws <see cref="ArgumentException"/> for a skeleton without usable legs).</param>
        /// <param name="settings">The bake's foot-locking settings.</param>
        /// <param name="where">The skeleton, for the message ("the model's skeleton", "the rig").</param>
        /// <exception cref="InvalidOperationException">The rig has no usable legs.</exception>
        internal static FootLocker ForBake(Func<FootRig> rig, FootLockSettings settings, string where)
        {
            try
            {
                return new FootLocker(rig(), settings);
            }
            catch (ArgumentException e)
            {
                throw new InvalidOperationException($"foot locking on {where}: {e.Message}; bake without foot locking (BakeSettings.FootLocking = null) for a skeleton without them", e);
            }
        }

        /// <summary>The rig.</summary>
        public FootRig Rig => _rig;

        /// <summary>The settings (validated on construction; do not change them afterwards).</summary>
        public FootLockSettings Settings => _settings;

        /// <summary>Frames of the last clip labelled or locked.</summary>
        public int FrameCount => _frames;

        /// <summary>
        /// After <see cref="Lock(MotionClip, IReadOnlyList{int})"/> or <see cref="Plan(MotionClip, IReadOnlyList{int})"/>: whether foot joint <paramref name="channel"/> (0 left ankle,
        /// 1 left toe, 2 right ankle, 3 right toe) is planted on <paramref name="frame"/>: held on its spot (not on a
        /// frame of a contact where the leg cannot reach the foot's spot: the foot is only kept as near it as the leg reaches).
        /// </summary>
        public bool IsPlanted(int frame, int channel)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            if ((uint)channel >= ChannelCount) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            // A foot one of whose joints is pulled towards the hips is off its spot as a whole (the other joint's solve moves with it).
            return _segment[channel * _capacity + frame] != 0 && !_beyondReach[channel * _capacity + frame] && !_beyondReach[(channel ^ 1) * _capacity + frame];
        }

        /// <summary>After <see cref="Plan(MotionClip, IReadOnlyList{int})"/>: how strongly (0..1) foot joint <paramref name="channel"/> is held on <paramref name="frame"/>.</summary>
        public double LockWeight(int frame, int channel)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            if ((uint)channel >= ChannelCount) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return _weight[channel * _capacity + frame];
        }

        /// <summary>After <see cref="Plan(MotionClip, IReadOnlyList{int})"/>: the ground height the locker estimated under foot joint <paramref name="channel"/> on <paramref name="frame"/>.</summary>
        public double GroundHeight(int frame, int channel)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            if ((uint)channel >= ChannelCount) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return _ground[channel * _capacity + frame];
        }

        /// <summary>After planning: where foot joint <paramref name="channel"/> is held on <paramref name="frame"/> (meaningful where <see cref="LockWeight"/> is above 0).</summary>
        internal Vector3D HeldAt(int frame, int channel)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            if ((uint)channel >= ChannelCount) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return Vector3D.Read(_anchor, (channel * _capacity + frame) * 3);
        }

        /// <summary>After <see cref="Plan(MotionClip, IReadOnlyList{int})"/>: foot joint <paramref name="channel"/>'s planted height above the ground (clip units).</summary>
        public double PlantedHeight(int channel) => _plantedHeight[channel];

        /// <summary>Plans and locks every non-key frame of <paramref name="clip"/> in place.</summary>
        /// <param name="clip">Motion on the rig's skeleton (e.g. a bake: key frames and filled frames).</param>
        /// <param name="keys">Frame indices of <paramref name="clip"/> that are keys (increasing, at least one): never changed, and the source of the ground.</param>
        public void Lock(MotionClip clip, IReadOnlyList<int> keys) => Lock(clip, keys, null);

        /// <summary>
        /// <see cref="Lock(MotionClip, IReadOnlyList{int})"/> with the contacts of the one contact source: on every frame
        /// <paramref name="contacts"/> has a prediction for (a model with a contact output filled it) a foot joint is
        /// planted where the prediction says; elsewhere (keys, SLERP's frames, null) the locker labels it.
        /// </summary>
        /// <param name="clip">Motion on the rig's skeleton.</param>
        /// <param name="keys">Frame indices of <paramref name="clip"/> that are keys.</param>
        /// <param name="contacts">Predicted contacts for the clip's frames (<see cref="FootContacts.FrameCount"/> = the clip's), or null.</param>
        public void Lock(MotionClip clip, IReadOnlyList<int> keys, FootContacts? contacts) => LockFrames(clip, keys, null, contacts);

        /// <summary><see cref="Lock(MotionClip, IReadOnlyList{int})"/> with the contacts given (<see cref="PlanWithContacts"/>), or labelled when null.</summary>
        internal void LockWithContacts(MotionClip clip, IReadOnlyList<int> keys, bool[]? contacts) => LockFrames(clip, keys, contacts, null);

        private void LockFrames(MotionClip clip, IReadOnlyList<int> keys, bool[]? given, FootContacts? predicted)
        {
            Plan(clip, keys, given, predicted);
            for (int f = 0; f < _frames; f++)
            {
                if (_isKey[f]) continue;
                LockFrame(f, clip.LocalPositions.AsSpan(clip.PositionIndex(f, 0), 3 * clip.Skeleton.JointCount), clip.LocalRotations.AsSpan(clip.RotationIndex(f, 0), 4 * clip.Skeleton.JointCount));
            }
        }

        /// <summary>
        /// Labels contacts and chooses where each planted joint is held on every frame of <paramref name="clip"/>,
        /// without changing it; <see cref="LockFrame"/> then applies one frame.
        /// </summary>
        public void Plan(MotionClip clip, IReadOnlyList<int> keys) => Plan(clip, keys, null, null);

        /// <summary><see cref="Plan(MotionClip, IReadOnlyList{int})"/> with predicted contacts where <paramref name="contacts"/> has them (see <see cref="Lock(MotionClip, IReadOnlyList{int}, FootContacts)"/>).</summary>
        public void Plan(MotionClip clip, IReadOnlyList<int> keys, FootContacts? contacts) => Plan(clip, keys, null, contacts);

        /// <summary>
        /// <see cref="Plan(MotionClip, IReadOnlyList{int})"/> with the contacts given instead of labelled (when not null): frames ×
        /// <see cref="ChannelCount"/> flags (a run of set flags is one contact). Everything after labelling — where a
        /// joint is held, reach, easing — is the same. The analysis of the locker alone (Tools~/Tests'
        /// FootLockingAnalysis) gives it the truth's contacts, to separate what locking reaches with contacts known
        /// from what labelling them from the filled motion loses.
        /// </summary>
        internal void PlanWithContacts(MotionClip clip, IReadOnlyList<int> keys, bool[]? contacts) => Plan(clip, keys, contacts, null);

        private void Plan(MotionClip clip, IReadOnlyList<int> keys, bool[]? contacts, FootContacts? predicted)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (predicted != null && predicted.FrameCount != clip.FrameCount) throw new ArgumentException($"contacts for {predicted.FrameCount} frames; expected the clip's {clip.FrameCount}", nameof(predicted));
            if (contacts != null && contacts.Length != clip.FrameCount * ChannelCount) throw new ArgumentException($"{contacts.Length} contact flags; expected frames × {ChannelCount} = {clip.FrameCount * ChannelCount}", nameof(contacts));
            if (keys == null || keys.Count == 0) throw new ArgumentException("expected at least one key frame", nameof(keys));
            if (!clip.Skeleton.HasSameHierarchy(_rig.Skeleton)) throw new ArgumentException("the clip is not on the rig's skeleton", nameof(clip));
            int frames = clip.FrameCount;
            Reserve(frames);
            _frames = frames;
            Array.Clear(_isKey, 0, _capacity);
            for (int i = 0; i < keys.Count; i++)
            {
                int k = keys[i];
                if ((uint)k >= (uint)frames) throw new ArgumentOutOfRangeException(nameof(keys), $"key {k} is not a frame of the clip (0..{frames - 1})");
                if (i > 0 && k <= keys[i - 1]) throw new ArgumentException($"key {k} after {keys[i - 1]}; expected increasing key frames", nameof(keys));
                _isKey[k] = true;
            }

            ReadFrames(clip);
            _keys = keys;
            EstimateGround(keys);
            double leg = _rig.LegLength;
            double dt = clip.FrameTime;
            int minFrames = Math.Max(1, (int)Math.Round(_settings.MinContactSeconds / dt));
            int ease = Math.Max(1, (int)Math.Round(_settings.EaseSeconds / dt));
            Array.Clear(_segment, 0, _segment.Length);
            Array.Clear(_weight, 0, _weight.Length);
            Array.Clear(_beyondReach, 0, _beyondReach.Length);
            for (int c = 0; c < ChannelCount; c++)
            {
                if (_channelJoint[c] < 0) continue;
                int row = c * _capacity;
                for (int f = 0; f < frames; f++) _ground[row + f] = GroundAt(_feet[(row + f) * 3], _feet[(row + f) * 3 + 2], f, keys);
                _plantedHeight[c] = PlantedHeightOf(c, leg, keys);
                for (int f = 0; f < frames; f++) _rise[f] = _feet[(row + f) * 3 + 1] - _ground[row + f] - _plantedHeight[c];
                int next = 1;
                LabelFromKeys(c, leg, keys, ease, dt, ref next);
                LabelFree(c, leg, dt, minFrames, ref next);
                if (contacts != null) Given(c, contacts, ref next);
                else if (predicted != null && predicted.AnyPredicted) Predicted(c, predicted, ref next);
                Separate(c, ease);
                Anchor(c, leg);
                PullIntoReach(c);
                Ease(c, ease);
            }

            _keys = null;
        }

        /// <summary>
        /// Locks one frame in place (allocation-free): after <see cref="Plan(MotionClip, IReadOnlyList{int})"/>, moves the legs of frame
        /// <paramref name="frame"/> so that its planted joints reach their targets. Changes the thigh, knee and
        /// ankle rotations of a leg with a planted joint; nothing else.
        /// </summary>
        /// <param name="frame">A frame of the planned clip.</param>
        /// <param name="localPositions">That frame's joints × 3 local translations (the root's is its position).</param>
        /// <param name="localRotations">That frame's joints × 4 local rotations, changed in place.</param>
        public void LockFrame(int frame, ReadOnlySpan<double> localPositions, Span<double> localRotations)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            int cap = _capacity;
            bool any = false;
            for (int c = 0; c < ChannelCount; c++) any |= _weight[c * cap + frame] > 0;
            if (!any) return;

            for (int c = 0; c < ChannelCount; c++)
            {
                _frameWeights[c] = _weight[c * cap + frame];
                Copy(_anchor, (c * cap + frame) * 3, _frameTargets, 3 * c);
            }

            _pinning.ComputeGlobals(localPositions, localRotations);
            _pinning.Pin(_frameWeights, _frameTargets, localRotations);
        }

        private void Reserve(int frames)
        {
            if (frames <= _capacity) return;
            int cap = Math.Max(frames, 2 * _capacity);
            _capacity = cap;
            _feet = new double[ChannelCount * cap * 3];
            _hips = new double[2 * cap * 3];
            _toeVector = new double[2 * cap * 3];
            _ground = new double[ChannelCount * cap];
            _support = new double[3 * cap];
            _gap = new int[cap];
            _segment = new int[ChannelCount * cap];
            _rise = new double[cap];
            _anchor = new double[ChannelCount * cap * 3];
            _weight = new double[ChannelCount * cap];
            _isKey = new bool[cap];
            _beyondReach = new bool[ChannelCount * cap];
            _scratch = new double[3 * cap];
        }

        /// <summary>FK of every frame: foot joint and hip positions, toe vectors.</summary>
        private void ReadFrames(MotionClip clip)
        {
            Skeleton s = clip.Skeleton;
            int j = s.JointCount, cap = _capacity;
            for (int f = 0; f < _frames; f++)
            {
                ReadOnlySpan<double> lp = clip.LocalPositions.AsSpan(clip.PositionIndex(f, 0), 3 * j);
                _pinning.ComputeGlobals(lp, clip.LocalRotations.AsSpan(clip.RotationIndex(f, 0), 4 * j));
                double[] globals = _pinning.GlobalPositions;
                for (int c = 0; c < ChannelCount; c++)
                {
                    if (_channelJoint[c] >= 0) Array.Copy(globals, 3 * _channelJoint[c], _feet, (c * cap + f) * 3, 3);
                }

                for (int side = 0; side < 2; side++)
                {
                    Leg leg = _rig[side];
                    Array.Copy(globals, 3 * leg.Hip, _hips, (side * cap + f) * 3, 3);
                    Vector3D toe = leg.HasToe ? Vector3D.Read(globals, 3 * leg.Toe) - Vector3D.Read(globals, 3 * leg.Ankle) : Vector3D.Zero;
                    toe.Write(_toeVector, (side * cap + f) * 3);
                    if (f == 0)
                    {
                        _thigh[side] = (Vector3D.Read(globals, 3 * leg.Knee) - Vector3D.Read(globals, 3 * leg.Hip)).Length;
                        _shin[side] = (Vector3D.Read(globals, 3 * leg.Ankle) - Vector3D.Read(globals, 3 * leg.Knee)).Length;
                    }
                }
            }
        }

        /// <summary>The joint of each contact channel (ankle, toe per side; −1 for a toe the rig lacks).</summary>
        internal static void ChannelJoints(FootRig rig, int[] joints)
        {
            for (int side = 0; side < 2; side++)
            {
                Leg leg = rig[side];
                joints[2 * side] = leg.Ankle;
                joints[2 * side + 1] = leg.HasToe ? leg.Toe : -1;
            }
        }

        /// <summary>
        /// The most a foot joint's planted height may be (leg lengths): its height above the rig's lowest foot joint
        /// when it stands flat-footed, plus 1 % (a toe on the ground, an ankle a few centimetres up), so that a joint the
        /// keys never show on the ground is not planted in the air.
        /// </summary>
        internal static void StandingHeights(FootRig rig, double[] heights)
        {
            // Flat-footed: the ankle above the toe by at most the foot's drop in the model T-pose (30° below forward).
            for (int side = 0; side < 2; side++)
            {
                Leg leg = rig[side];
                double foot = leg.HasToe ? rig.RestLength(leg.Ankle, leg.Toe) : 0;
                heights[2 * side] = (0.5 * foot) / rig.LegLength + 0.01;
                heights[2 * side + 1] = 0.01;
            }
        }

        private static void Copy(double[] from, int i, double[] to, int j)
        {
            to[j] = from[i];
            to[j + 1] = from[i + 1];
            to[j + 2] = from[i + 2];
        }

        private static Vector3D Lerp(Vector3D a, Vector3D b, double t) => LegPinning.Lerp(a, b, t);
    }
}
