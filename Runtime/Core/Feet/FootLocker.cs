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
    public sealed class FootLocker
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
        /// After <see cref="Lock"/> or <see cref="Plan"/>: whether foot joint <paramref name="channel"/> (0 left ankle,
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

        /// <summary>After <see cref="Plan"/>: how strongly (0..1) foot joint <paramref name="channel"/> is held on <paramref name="frame"/>.</summary>
        public double LockWeight(int frame, int channel)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            if ((uint)channel >= ChannelCount) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return _weight[channel * _capacity + frame];
        }

        /// <summary>After <see cref="Plan"/>: the ground height the locker estimated under foot joint <paramref name="channel"/> on <paramref name="frame"/>.</summary>
        public double GroundHeight(int frame, int channel)
        {
            if ((uint)frame >= (uint)_frames) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame}; expected 0..{_frames - 1}");
            if ((uint)channel >= ChannelCount) throw new ArgumentOutOfRangeException(nameof(channel), "expected a channel 0..3");
            return _ground[channel * _capacity + frame];
        }

        /// <summary>After <see cref="Plan"/>: foot joint <paramref name="channel"/>'s planted height above the ground (clip units).</summary>
        public double PlantedHeight(int channel) => _plantedHeight[channel];

        /// <summary>Plans and locks every non-key frame of <paramref name="clip"/> in place.</summary>
        /// <param name="clip">Motion on the rig's skeleton (e.g. a bake: key frames and filled frames).</param>
        /// <param name="keys">Frame indices of <paramref name="clip"/> that are keys (increasing, at least one): never changed, and the source of the ground.</param>
        public void Lock(MotionClip clip, IReadOnlyList<int> keys) => LockWithContacts(clip, keys, null);

        /// <summary><see cref="Lock"/> with the contacts given (<see cref="PlanWithContacts"/>), or labelled when null.</summary>
        internal void LockWithContacts(MotionClip clip, IReadOnlyList<int> keys, bool[]? contacts)
        {
            PlanWithContacts(clip, keys, contacts);
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
        public void Plan(MotionClip clip, IReadOnlyList<int> keys) => PlanWithContacts(clip, keys, null);

        /// <summary>
        /// <see cref="Plan"/> with the contacts given instead of labelled (when not null): frames ×
        /// <see cref="ChannelCount"/> flags (a run of set flags is one contact). Everything after labelling — where a
        /// joint is held, reach, easing — is the same. The analysis of the locker alone (Tools~/Tests'
        /// FootLockingAnalysis) gives it the truth's contacts, to separate what locking reaches with contacts known
        /// from what labelling them from the filled motion loses.
        /// </summary>
        internal void PlanWithContacts(MotionClip clip, IReadOnlyList<int> keys, bool[]? contacts)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
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
                Separate(c, ease);
                Anchor(c, leg);
                PullIntoReach(c);
                Ease(c, ease);
            }

            _keys = null;
        }

        /// <summary>
        /// Locks one frame in place (allocation-free): after <see cref="Plan"/>, moves the legs of frame
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

        /// <summary>
        /// Where the ground is at each key: the lowest foot joint's height and horizontal position (a key whose lowest
        /// joint is above its neighbours' mean, in a jump or a run's flight, takes that mean); each frame's gap.
        /// </summary>
        private void EstimateGround(IReadOnlyList<int> keys)
        {
            int n = keys.Count;
            for (int i = 0; i < n; i++) Support(i, LowestFoot(keys[i], 0, 0, 0), keys[i]);

            // On a slope a foot swinging behind may be lower than the one planted ahead: pick again the lowest
            // foot joint relative to the slope the first guess shows around each key (the previous values are in _scratch).
            double[] first = _scratch;
            Array.Copy(_support, first, 3 * n);
            for (int i = 0; i < n; i++)
            {
                int p = Math.Max(0, i - 1), q = Math.Min(n - 1, i + 1);
                double dx = first[3 * q] - first[3 * p], dz = first[3 * q + 1] - first[3 * p + 1];
                double d = Math.Sqrt(dx * dx + dz * dz);
                if (d < 0.25 * _rig.LegLength) continue;
                double slope = Math.Max(-0.5, Math.Min(0.5, (first[3 * q + 2] - first[3 * p + 2]) / d));
                Support(i, LowestFoot(keys[i], slope, dx / d, dz / d), keys[i]);
            }

            double previous = _support[2];
            for (int i = 0; i < n; i++)
            {
                double here = _support[3 * i + 2];
                double around = n == 1 ? here : i == 0 ? _support[3 * 1 + 2] : i == n - 1 ? previous : 0.5 * (previous + _support[3 * (i + 1) + 2]);
                previous = here;
                _support[3 * i + 2] = Math.Min(here, around);
            }

            int gap = 0;
            for (int f = 0; f < _frames; f++)
            {
                while (gap + 2 < n && f > keys[gap + 1]) gap++;
                _gap[f] = gap;
            }
        }

        /// <summary>
        /// The ground height at horizontal position (x, z) on frame f: on the line through the two keys' ground points
        /// around the frame (so a slope is followed under each foot), or, when those points are close together, their
        /// heights interpolated in time.
        /// </summary>
        private double GroundAt(double x, double z, int f, IReadOnlyList<int> keys)
        {
            int n = keys.Count;
            if (n == 1) return _support[2];
            int i = _gap[f];
            int a = keys[i], b = keys[i + 1];
            double ax = _support[3 * i], az = _support[3 * i + 1], ga = _support[3 * i + 2];
            double dx = _support[3 * (i + 1)] - ax, dz = _support[3 * (i + 1) + 1] - az, gb = _support[3 * (i + 1) + 2];
            double d = Math.Sqrt(dx * dx + dz * dz);
            if (d < 0.25 * _rig.LegLength)
            {
                double t = Math.Max(0, Math.Min(1, (f - a) / (double)(b - a)));
                return ga + t * (gb - ga);
            }

            double slope = Math.Max(-0.5, Math.Min(0.5, (gb - ga) / d));
            double u = Math.Max(-d, Math.Min(2 * d, ((x - ax) * dx + (z - az) * dz) / d));
            return ga + slope * u;
        }

        /// <summary>The channel of the lowest foot joint on a frame, heights measured from a plane rising by <paramref name="slope"/> along (dx, dz).</summary>
        private int LowestFoot(int frame, double slope, double dx, double dz)
        {
            int lowest = -1;
            double best = double.PositiveInfinity;
            for (int c = 0; c < ChannelCount; c++)
            {
                if (_channelJoint[c] < 0) continue;
                int i = (c * _capacity + frame) * 3;
                double height = _feet[i + 1] - slope * (_feet[i] * dx + _feet[i + 2] * dz);
                if (height < best)
                {
                    best = height;
                    lowest = c;
                }
            }

            return lowest;
        }

        private void Support(int key, int channel, int frame)
        {
            int at = (channel * _capacity + frame) * 3;
            _support[3 * key] = _feet[at];
            _support[3 * key + 1] = _feet[at + 2];
            _support[3 * key + 2] = _feet[at + 1];
        }

        /// <summary>The 10th percentile of the joint's height above the ground at the keys, between 1 % of a leg below the ground and its standing height.</summary>
        private double PlantedHeightOf(int c, double leg, IReadOnlyList<int> keys)
        {
            // From the keys only: they are real poses, while filled motion may sink a foot into the floor.
            double[] h = _scratch;
            int n = keys.Count;
            for (int i = 0; i < n; i++) h[i] = _feet[(c * _capacity + keys[i]) * 3 + 1] - _ground[c * _capacity + keys[i]];
            Array.Sort(h, 0, n);
            double low = h[(int)(0.1 * (n - 1))];
            return Math.Max(-0.01 * leg, Math.Min(low, _maxPlantedHeight[c] * leg));
        }

        /// <summary>
        /// Contacts that the keys vouch for: a foot joint planted on a key (at most <see cref="FootLockSettings.EnterHeight"/>
        /// above its planted height there) stays planted into the gaps beside it while the filled motion keeps it
        /// low and near that spot; two planted keys at the same spot with the foot kept low between them make one
        /// contact across the gap.
        /// </summary>
        private void LabelFromKeys(int c, double leg, IReadOnlyList<int> keys, int ease, double dt, ref int next)
        {
            double fast = _settings.HoldSpeed * leg;
            int cap = _capacity, row = c * cap;
            double enter = _settings.EnterHeight * leg, exit = _settings.ExitHeight * leg;
            double hold = _settings.HoldDistance * leg, step = _settings.StepHeight * leg;
            int first = keys[0];
            if (_rise[first] <= enter) _segment[row + first] = next++;
            // A key's contact carries on into the gap after it only as far as the next key (never over it).
            for (int i = 0; i + 1 < keys.Count; i++)
            {
                int a = keys[i], b = keys[i + 1];
                bool plantedA = _rise[a] <= enter, plantedB = _rise[b] <= enter;
                if (plantedA && plantedB && (Vector3D.Read(_feet, (row + a) * 3) - Vector3D.Read(_feet, (row + b) * 3)).Length <= _settings.BridgeDistance * leg && MaxRise(a, b) <= step)
                {
                    // One contact across the gap (a foot standing through it).
                    for (int f = a + 1; f <= b; f++) _segment[row + f] = _segment[row + a];
                    continue;
                }

                int backStart = b;
                if (plantedB)
                {
                    int id = next++;
                    _segment[row + b] = id;
                    for (int f = b - 1; f > a && _rise[f] <= exit && Horizontal(c, f, b) <= hold && HorizontalSpeed(c, f, dt) <= fast; f--)
                    {
                        _segment[row + f] = id;
                        backStart = f;
                    }
                }

                if (!plantedA) continue;
                int forwardEnd = a;
                for (int f = a + 1; f < backStart && _rise[f] <= exit && Horizontal(c, f, a) <= hold && HorizontalSpeed(c, f, dt) <= fast; f++)
                {
                    _segment[row + f] = _segment[row + a];
                    forwardEnd = f;
                }

                // Two different contacts in one gap: leave room to ease from one to the other.
                while (plantedB && backStart - forwardEnd - 1 < ease && (forwardEnd > a || backStart < b))
                {
                    if (forwardEnd - a >= b - backStart && forwardEnd > a) _segment[row + forwardEnd--] = 0;
                    else if (backStart < b) _segment[row + backStart++] = 0;
                    else break;
                }
            }
        }

        /// <summary>
        /// Contacts the filled motion shows by itself (between keys that are not planted there): with hysteresis
        /// on height and speed (<see cref="NextPlanted"/>), at least <paramref name="minFrames"/> long; one that
        /// touches a key's contact joins it.
        /// </summary>
        private void LabelFree(int c, double leg, double dt, int minFrames, ref int next)
        {
            int cap = _capacity, row = c * cap, n = _frames;
            bool planted = false;
            int start = 0;
            for (int f = 0; f <= n; f++)
            {
                // A key joins a free contact only if it is planted by its own height (keys are where contacts are anchored).
                bool free = f < n && _segment[row + f] == 0 && (!_isKey[f] || _rise[f] <= _settings.EnterHeight * leg);
                bool now = free && NextPlanted(planted, _rise[f] / leg, HorizontalSpeed(c, f, dt) / leg, _settings);
                if (now && !planted) start = f;
                if (planted && !now)
                {
                    // A contact start..f-1 ends: it joins a key's contact it touches, else stands alone if long enough.
                    int id = start > 0 && _segment[row + start - 1] != 0 ? _segment[row + start - 1]
                        : f < n && _segment[row + f] != 0 ? _segment[row + f]
                        : f - start >= minFrames ? next++ : 0;
                    for (int g = start; g < f; g++) _segment[row + g] = id;
                }

                planted = now;
            }
        }

        /// <summary>Channel c's contacts from <paramref name="contacts"/> (frames × channels) instead of the labels: one contact per run of set flags.</summary>
        private void Given(int c, bool[] contacts, ref int next)
        {
            int row = c * _capacity;
            for (int f = 0; f < _frames; f++)
            {
                _segment[row + f] = !contacts[f * ChannelCount + c] ? 0
                    : f > 0 && _segment[row + f - 1] != 0 ? _segment[row + f - 1]
                    : next++;
            }
        }

        /// <summary>
        /// The contact state machine with hysteresis: a joint <paramref name="rise"/> leg lengths above its planted
        /// height moving at <paramref name="speed"/> leg lengths per second becomes planted below the entry
        /// thresholds and stays planted until it passes an exit threshold.
        /// </summary>
        internal static bool NextPlanted(bool planted, double rise, double speed, FootLockSettings settings) => planted
            ? rise <= settings.ExitHeight && speed <= settings.ExitSpeed
            : rise <= settings.EnterHeight && speed <= settings.EnterSpeed;

        private double MaxRise(int a, int b)
        {
            double most = double.NegativeInfinity;
            for (int f = a; f <= b; f++) most = Math.Max(most, _rise[f]);
            return most;
        }

        private double Horizontal(int c, int f, int g)
        {
            int i = (c * _capacity + f) * 3, j = (c * _capacity + g) * 3;
            double dx = _feet[i] - _feet[j], dz = _feet[i + 2] - _feet[j + 2];
            return Math.Sqrt(dx * dx + dz * dz);
        }

        private double HorizontalSpeed(int c, int f, double dt)
        {
            int n = _frames;
            if (n < 2) return 0;
            int a = Math.Max(0, f - 1), b = Math.Min(n - 1, f + 1);
            return Horizontal(c, a, b) / ((b - a) * dt);
        }

        /// <summary>
        /// Leaves at least <paramref name="ease"/> frames between two different contacts of channel c (trimming filled
        /// frames off the longer one), so that the joint eases from one spot to the next instead of jumping.
        /// </summary>
        private void Separate(int c, int ease)
        {
            int row = c * _capacity, n = _frames;
            for (int e = 0; e + 1 < n; e++)
            {
                int id = _segment[row + e];
                if (id == 0 || _segment[row + e + 1] == id) continue;
                int s = e + 1;
                while (s < n && _segment[row + s] == 0 && s - e - 1 < ease) s++;
                if (s >= n || _segment[row + s] == 0 || _segment[row + s] == id) continue;
                // Contact `id` ends at e, another starts at s, fewer than `ease` free frames between them.
                int other = _segment[row + s];
                while (s - e - 1 < ease)
                {
                    bool trimEnd = !_isKey[e] && _segment[row + e] == id && (RunLength(row, e, -1) >= RunLength(row, s, +1) || _isKey[s] || _segment[row + s] != other);
                    if (trimEnd) _segment[row + e--] = 0;
                    else if (!_isKey[s] && _segment[row + s] == other) _segment[row + s++] = 0;
                    else break;
                }
            }
        }

        /// <summary>Frames of the run containing frame f, counted from f in direction <paramref name="step"/>.</summary>
        private int RunLength(int row, int f, int step)
        {
            int id = _segment[row + f], count = 0;
            while (f >= 0 && f < _frames && _segment[row + f] == id)
            {
                count++;
                f += step;
            }

            return count;
        }

        /// <summary>The next contact of a channel's row at or after frame <paramref name="s"/>: its first (s) and last (e) frame; false when none is left.</summary>
        private bool NextContact(int row, ref int s, out int e)
        {
            int n = _frames;
            while (s < n && _segment[row + s] == 0) s++;
            e = s;
            if (s >= n) return false;
            int id = _segment[row + s];
            while (e + 1 < n && _segment[row + e + 1] == id) e++;
            return true;
        }

        /// <summary>Where channel c is held on each of its contact frames (per contact: through its keys, or its mean).</summary>
        private void Anchor(int c, double leg)
        {
            int cap = _capacity, row = c * cap, n = _frames;
            for (int s = 0; NextContact(row, ref s, out int e); s = e + 1)
            {
                int firstKey = -1, lastKey = -1;
                for (int f = s; f <= e; f++)
                {
                    if (!_isKey[f]) continue;
                    if (firstKey < 0) firstKey = f;
                    lastKey = f;
                }

                if (firstKey >= 0)
                {
                    // Through the keys: held where they have it, linearly from key to key.
                    int previousKey = firstKey;
                    for (int f = s; f <= e; f++)
                    {
                        int at = (row + f) * 3;
                        if (f <= firstKey || f >= lastKey)
                        {
                            Copy(_feet, (row + (f <= firstKey ? firstKey : lastKey)) * 3, _anchor, at);
                            continue;
                        }

                        if (_isKey[f])
                        {
                            previousKey = f;
                            Copy(_feet, at, _anchor, at);
                            continue;
                        }

                        int nextKey = f + 1;
                        while (!_isKey[nextKey]) nextKey++;
                        double t = (f - previousKey) / (double)(nextKey - previousKey);
                        Lerp(Vector3D.Read(_feet, (row + previousKey) * 3), Vector3D.Read(_feet, (row + nextKey) * 3), t).Write(_anchor, at);
                    }
                }
                else
                {
                    // Between keys: its mean position, at a height near its planted height.
                    double x = 0, rise = 0, z = 0;
                    for (int f = s; f <= e; f++)
                    {
                        int i = (row + f) * 3;
                        x += _feet[i];
                        rise += _rise[f];
                        z += _feet[i + 2];
                    }

                    int count = e - s + 1;
                    rise = Math.Max(-0.01 * leg, Math.Min(0.01 * leg, rise / count));
                    var held = new Vector3D(x / count, GroundAt(x / count, z / count, s, _keys!) + _plantedHeight[c] + rise, z / count);
                    for (int f = s; f <= e; f++) held.Write(_anchor, (row + f) * 3);
                }

            }
        }

        /// <summary>
        /// Moves each contact frame's target that the leg cannot reach towards where the filled motion has the joint,
        /// just as far as the leg reaches. Dropping the frame instead would split the contact, and the rest of it would be
        /// held at a spot of its own: the foot would jump there and back. Pulled, it slides only as much as the hips
        /// outrun it, and stays on its spot wherever the leg reaches.
        /// </summary>
        private void PullIntoReach(int c)
        {
            int cap = _capacity, side = c / 2;
            bool toe = (c & 1) == 1;
            double full = TwoBoneIk.MaxExtension * (_thigh[side] + _shin[side]);
            double reach = _settings.MaxReach * (_thigh[side] + _shin[side]);
            for (int f = 0; f < _frames; f++)
            {
                if (_segment[c * cap + f] == 0 || _isKey[f]) continue;
                int at = (c * cap + f) * 3;
                Vector3D anchor = Vector3D.Read(_anchor, at);
                Vector3D hip = Vector3D.Read(_hips, (side * cap + f) * 3);
                // The ankle's target (a toe's less the foot), relative to the hip.
                Vector3D fromHip = toe ? anchor - Vector3D.Read(_toeVector, (side * cap + f) * 3) - hip : anchor - hip;
                // A leg already that straight in the motion may stay so (a standing leg); only a longer reach is refused.
                double now = (Vector3D.Read(_feet, ((2 * side) * cap + f) * 3) - hip).Length;
                double limit = Math.Max(reach, Math.Min(now + 1e-3 * _rig.LegLength, full));
                if (fromHip.Length <= limit) continue;
                // The first point on the way from the target to the filled joint that is within the limit:
                // |fromHip + t·towards| = limit, smallest t in [0, 1] (t = 1, the filled joint, is within it).
                Vector3D towards = Vector3D.Read(_feet, at) - anchor;
                double a = Vector3D.Dot(towards, towards), b = Vector3D.Dot(fromHip, towards), cc = Vector3D.Dot(fromHip, fromHip) - limit * limit;
                double disc = b * b - a * cc;
                double t = a <= 0 || disc < 0 ? 1 : Math.Max(0, Math.Min(1, (-b - Math.Sqrt(disc)) / a));
                (anchor + t * towards).Write(_anchor, at);
                _beyondReach[c * cap + f] = true;
            }
        }

        /// <summary>Weights of channel c: 1 on contact frames, easing to 0 over <paramref name="ease"/> frames before and after, never across a key or into another contact.</summary>
        private void Ease(int c, int ease)
        {
            int cap = _capacity, row = c * cap, n = _frames;
            for (int f = 0; f < n; f++) _weight[row + f] = _segment[row + f] != 0 ? 1 : 0;
            for (int s = 0; NextContact(row, ref s, out int e); s = e + 1)
            {
                for (int d = 1; d <= ease; d++)
                {
                    int f = s - d;
                    if (f < 0 || _isKey[f] || _segment[row + f] != 0) break;
                    Blend(row, f, s, d, ease);
                }

                for (int d = 1; d <= ease; d++)
                {
                    int f = e + d;
                    if (f >= n || _isKey[f] || _segment[row + f] != 0) break;
                    Blend(row, f, e, d, ease);
                }

            }
        }

        /// <summary>Frame f, d frames outside the contact frame <paramref name="edge"/>, eases towards that frame's target (the nearer contact wins).</summary>
        private void Blend(int row, int f, int edge, int d, int ease)
        {
            double x = 1 - d / (double)(ease + 1);
            double w = x * x * (3 - 2 * x);
            if (_settings.EaseReach > 0)
            {
                // A joint the filled motion has carried far from the target is pulled less (a swinging foot is not dragged back).
                double far = (Vector3D.Read(_anchor, (row + edge) * 3) - Vector3D.Read(_feet, (row + f) * 3)).Length;
                w *= Math.Max(0, 1 - far / (_settings.EaseReach * _rig.LegLength));
            }

            if (w <= _weight[row + f]) return;
            _weight[row + f] = w;
            Copy(_anchor, (row + edge) * 3, _anchor, (row + f) * 3);
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
                double foot = leg.HasToe ? Vector3D.Read(rig.Skeleton.OffsetSpan, 3 * leg.Toe).Length : 0;
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
