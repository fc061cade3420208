using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>
    /// Sparse keys → dense motion: given a clip and the frame indices of its keys, fills every gap between
    /// consecutive keys, in order, with any <see cref="IInbetweener"/> and returns the clip from the first
    /// to the last key with the key frames copied exactly.
    /// </summary>
    /// <remarks>
    /// <para>Past context of a gap: up to <see cref="BakeSettings.PastFrames"/> consecutive frames ending
    /// at the key before it — key frames and frames this baker already filled alike, since a model was
    /// trained on consecutive past frames and with keys every K &gt; 1 frames the frames right before a
    /// key are always filled ones (<see cref="BakeSettings.FilledFramesAsContext"/> = false limits it to
    /// key frames). The future is the next key. At the first gap only the first key
    /// exists; fewer frames than wanted are fed under <see cref="BakeSettings.ShortContext"/>.</para>
    /// <para>Refused (<see cref="KeyLayoutException"/>): fewer than two keys, keys out of range, not
    /// increasing or repeated, and a gap the graph cannot take even with one past key (1 + n beyond the
    /// largest frame index). When a gap fits only with fewer past keys than wanted, fewer are fed. Gaps
    /// outside the trained ranges are baked and named in <see cref="BakePlan.Warnings"/>.</para>
    /// <para>With <see cref="BakeSettings.FootLocking"/> the filled frames are then foot-locked
    /// (<see cref="FootLocker"/>): planted feet held still, key frames untouched; where the model predicted
    /// contacts (<see cref="Contacts"/>) they say which feet are planted.</para>
    /// <para>Buffers (one <see cref="Transition"/> per request shape, the root track) are reused across
    /// gaps and bakes. Not thread-safe.</para>
    /// </remarks>
    public sealed class ClipBaker
    {
        private readonly ShapeCache<Transition> _transitions = new ShapeCache<Transition>();
        private Skeleton? _transitionSkeleton;
        private double[] _root = Array.Empty<double>();
        private FootLocker? _locker;
        private readonly FootContacts _contacts = new FootContacts();
        private int[] _relativeKeys = Array.Empty<int>();

        /// <summary>Creates a baker over <paramref name="inbetweener"/> (not owned: the caller disposes it).</summary>
        public ClipBaker(IInbetweener inbetweener, BakeSettings settings)
        {
            Inbetweener = inbetweener ?? throw new ArgumentNullException(nameof(inbetweener));
            Settings = settings ?? throw new ArgumentNullException(nameof(settings));
            if (settings.PastFrames < 1) throw new ArgumentException($"past frames = {settings.PastFrames}; expected at least 1", nameof(settings));
            if (settings.MaxFrameIndex < 2) throw new ArgumentException($"largest frame index = {settings.MaxFrameIndex}; expected at least 2 (one past key, one missing frame, the target)", nameof(settings));
        }

        /// <summary>The in-betweener that fills the gaps.</summary>
        public IInbetweener Inbetweener { get; }

        /// <summary>Context, limits and trained ranges.</summary>
        public BakeSettings Settings { get; }

        /// <summary>
        /// The last bake's foot contacts, one row per frame of the baked clip: the model's predictions on the frames it
        /// filled when it has a contact output (<see cref="Transition.HasFootContacts"/>), none elsewhere (keys, SLERP,
        /// models without it), where lockers label them. Overwritten by the next bake.
        /// </summary>
        public FootContacts Contacts => _contacts;

        /// <summary>
        /// Checks the keys against a clip of <paramref name="frameCount"/> frames and the settings, and lays
        /// out every gap. Call it before long work: it refuses what cannot be baked.
        /// </summary>
        /// <param name="frameCount">Frames of the clip the keys index.</param>
        /// <param name="keys">Key frame indices, increasing, at least two.</param>
        /// <exception cref="KeyLayoutException">The keys cannot be baked; the message says why and what to do.</exception>
        public BakePlan Plan(int frameCount, IReadOnlyList<int> keys)
        {
            if (keys == null) throw new ArgumentNullException(nameof(keys));
            if (keys.Count < 2)
            {
                throw new KeyLayoutException($"{keys.Count} key(s) given", "expected at least two keys (a gap lies between two keys)");
            }

            var sorted = new int[keys.Count];
            for (int i = 0; i < keys.Count; i++)
            {
                int k = keys[i];
                if (k < 0 || k >= frameCount)
                {
                    throw new KeyLayoutException($"key {k} is outside the clip's frames 0..{frameCount - 1}", "expected frame indices of the clip");
                }

                if (i > 0 && k == keys[i - 1])
                {
                    throw new KeyLayoutException($"key {k} is given twice", "expected each key frame once");
                }

                if (i > 0 && k < keys[i - 1])
                {
                    throw new KeyLayoutException($"key {k} comes after key {keys[i - 1]}", "expected increasing frame indices");
                }

                sorted[i] = k;
            }

            var gaps = new List<BakeGap>(sorted.Length - 1);
            var longGaps = new List<BakeGap>();
            var shortGaps = new List<BakeGap>();
            var pastOutside = new List<BakeGap>();
            var capped = new List<BakeGap>();
            int first = sorted[0];
            for (int i = 0; i + 1 < sorted.Length; i++)
            {
                int start = sorted[i], end = sorted[i + 1];
                int n = end - start - 1;
                if (n == 0) continue;
                int fit = Settings.MaxFrameIndex - n; // the most past keys this gap can have
                if (fit < 1)
                {
                    throw new KeyLayoutException(
                        $"the gap between keys {start} and {end} has {n} missing frames, more than {Settings.Name} can take (1 past key + {n} missing + the target needs frame index {n + 1} > its largest, {Settings.MaxFrameIndex})",
                        $"expected gaps of at most {Settings.MaxFrameIndex - 1} frames; add a key inside this gap");
                }

                int available = Math.Min(Settings.FilledFramesAsContext ? start - first + 1 : KeyRun(sorted, i), Settings.PastFrames);
                int pastFrames = PastContext.PastFrames(available, Settings.PastFrames, Settings.ShortContext);
                if (pastFrames > fit)
                {
                    pastFrames = fit;
                    available = Math.Min(available, fit);
                    capped.Add(new BakeGap(start, end, available, pastFrames));
                }

                var gap = new BakeGap(start, end, available, pastFrames);
                gaps.Add(gap);
                if (Settings.TrainedMissingFrames is { } m)
                {
                    if (n > m.Max) longGaps.Add(gap);
                    else if (n < m.Min) shortGaps.Add(gap);
                }

                if (Settings.TrainedPastFrames is { } p && (pastFrames < p.Min || pastFrames > p.Max)) pastOutside.Add(gap);
            }

            var warnings = new List<string>();
            if (Settings.TrainedMissingFrames is { } range)
            {
                if (longGaps.Count > 0)
                {
                    warnings.Add($"{Count(longGaps)} longer than the {range.Max} missing frames {Settings.Name} was trained on at most ({range.Min}..{range.Max}): {List(longGaps)}. Baked anyway; quality may drop, so add keys to shorten them.");
                }

                if (shortGaps.Count > 0)
                {
                    warnings.Add($"{Count(shortGaps)} shorter than the {range.Min} missing frames {Settings.Name} was trained on at least ({range.Min}..{range.Max}): {List(shortGaps)}. Baked anyway.");
                }
            }

            if (pastOutside.Count > 0 && Settings.TrainedPastFrames is { } trained)
            {
                warnings.Add($"{Count(pastOutside)} fed a number of past keys outside the {trained.Min}..{trained.Max} {Settings.Name} was trained on: {ListPast(pastOutside)}. Baked anyway.");
            }

            if (capped.Count > 0)
            {
                warnings.Add($"{Count(capped)} too long for {Settings.PastFrames} past keys within frame index {Settings.MaxFrameIndex}: {List(capped)}. Fed with fewer past keys.");
            }

            return new BakePlan(frameCount, sorted, gaps.ToArray(), warnings.ToArray());
        }

        /// <summary>
        /// Bakes <paramref name="source"/>: a new clip of <see cref="BakePlan.FrameCount"/> frames (source
        /// frames FirstKey..LastKey) whose key frames are the source's, copied exactly, and whose other
        /// frames are filled gap by gap. Filled frames' non-root joints sit at the skeleton's offsets.
        /// </summary>
        /// <param name="source">The clip the keys index; only its key frames are read.</param>
        /// <param name="plan">From <see cref="Plan"/> for this clip's frame count.</param>
        /// <param name="progress">Receives the number of gaps filled so far (0, then after every gap; of <c>plan.Gaps.Count</c>).</param>
        /// <exception cref="ArgumentException">The plan was made for another frame count.</exception>
        public MotionClip Bake(MotionClip source, BakePlan plan, IProgress<int>? progress = null)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            int frames = plan.FrameCount;
            int j = source.Skeleton.JointCount;
            var positions = new double[frames * j * 3];
            var rotations = new double[frames * j * 4];
            var result = new MotionClip(source.Skeleton, frames, source.FrameTime, positions, rotations);
            Bake(source, plan, result, progress);
            return result;
        }

        /// <summary>
        /// <see cref="Bake(MotionClip, BakePlan, IProgress{int})"/> into an existing clip of
        /// <see cref="BakePlan.FrameCount"/> frames on the same skeleton (its buffers are overwritten), so
        /// repeated bakes allocate nothing once every request shape has been seen (with an in-betweener that
        /// allocates nothing per call, such as SLERP or the ONNX Runtime model).
        /// </summary>
        public void Bake(MotionClip source, BakePlan plan, MotionClip destination, IProgress<int>? progress = null)
        {
            if (source == null) throw new ArgumentNullException(nameof(source));
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            if (destination == null) throw new ArgumentNullException(nameof(destination));
            if (plan.SourceFrameCount != source.FrameCount)
            {
                throw new ArgumentException($"the plan is for {plan.SourceFrameCount} frames but the clip has {source.FrameCount}; plan again for this clip", nameof(plan));
            }

            int frames = plan.FrameCount;
            Skeleton skeleton = source.Skeleton;
            int j = skeleton.JointCount;
            if (destination.FrameCount != frames || destination.Skeleton.JointCount != j)
            {
                throw new ArgumentException($"the destination has {destination.FrameCount} frames of {destination.Skeleton.JointCount} joints; expected {frames} frames of {j}", nameof(destination));
            }

            int first = plan.FirstKey;
            double[] rotations = destination.LocalRotations;
            double[] positions = destination.LocalPositions;
            if (_root.Length < frames * 3) _root = new double[frames * 3];
            double[] root = _root;
            int posStride = j * 3, rotStride = j * 4;
            foreach (int key in plan.KeyArray)
            {
                int f = key - first;
                Array.Copy(source.LocalPositions, key * posStride, positions, f * posStride, posStride);
                Array.Copy(source.LocalRotations, key * rotStride, rotations, f * rotStride, rotStride);
                Array.Copy(source.LocalPositions, key * posStride, root, f * 3, 3);
            }

            ReadOnlySpan<double> offsets = skeleton.OffsetSpan;
            _contacts.Clear(frames);
            int done = 0;
            progress?.Report(0);
            foreach (BakeGap gap in plan.GapArray)
            {
                int n = gap.MissingFrames;
                int start = gap.StartKey - first;
                Transition t = TransitionFor(skeleton, gap.PastFrames, n);
                PastContext.FillPast(t, root, rotations, start, gap.PastAvailable);
                PastContext.FillTarget(t, root, rotations, gap.EndKey - first);
                Inbetweener.Inbetween(t);
                if (t.HasFootContacts) _contacts.SetPredicted(start + 1, n, t.FootContacts, t.ContactThreshold);
                Array.Copy(t.RootPositions, 0, root, (start + 1) * 3, n * 3);
                Array.Copy(t.LocalRotations, 0, rotations, (start + 1) * rotStride, n * rotStride);
                for (int k = 0; k < n; k++)
                {
                    int f = start + 1 + k;
                    offsets.CopyTo(positions.AsSpan(f * posStride, posStride));
                    Array.Copy(t.RootPositions, k * 3, positions, f * posStride, 3);
                }

                done++;
                progress?.Report(done);
            }

            if (Settings.FootLocking != null) LockFeet(destination, plan);
        }

        /// <summary>Holds planted feet still on the filled frames (<see cref="BakeSettings.FootLocking"/>); keys stay as they are.</summary>
        private void LockFeet(MotionClip clip, BakePlan plan)
        {
            if (_locker == null || !ReferenceEquals(_locker.Rig.Skeleton, clip.Skeleton) && !_locker.Rig.Skeleton.HasSameHierarchy(clip.Skeleton))
            {
                _locker = FootLocker.ForBake(() => FootRig.ForModel(clip.Skeleton), Settings.FootLocking!, "the model's skeleton");
            }

            int[] keys = plan.KeyArray;
            if (_relativeKeys.Length != keys.Length) _relativeKeys = new int[keys.Length];
            for (int i = 0; i < keys.Length; i++) _relativeKeys[i] = keys[i] - plan.FirstKey;
            _locker.Lock(clip, _relativeKeys, _contacts);
        }

        private Transition TransitionFor(Skeleton skeleton, int past, int missing)
        {
            if (!ReferenceEquals(skeleton, _transitionSkeleton))
            {
                _transitions.Clear();
                _transitionSkeleton = skeleton;
            }

            return _transitions.Find(past, missing) ?? _transitions.Add(past, missing, new Transition(skeleton, past, missing));
        }

        /// <summary>How many keys end at keys[i] without a frame between them (≥ 1).</summary>
        private static int KeyRun(int[] keys, int i)
        {
            int run = 1;
            while (i - run >= 0 && keys[i - run] == keys[i] - run) run++;
            return run;
        }

        // Warnings read as sentences: "2 gaps are shorter than … (5..39): keys 450–454 (3 missing), keys …. Baked anyway."
        private static string Count(List<BakeGap> gaps) => gaps.Count == 1 ? "1 gap is" : gaps.Count.ToString(CultureInfo.InvariantCulture) + " gaps are";

        private static string List(List<BakeGap> gaps)
        {
            var sb = new StringBuilder();
            AppendList(sb, gaps, g => $"keys {g.StartKey}–{g.EndKey} ({g.MissingFrames} missing)");
            return sb.ToString();
        }

        private static string ListPast(List<BakeGap> gaps)
        {
            var sb = new StringBuilder();
            AppendList(sb, gaps, g => $"keys {g.StartKey}–{g.EndKey} ({g.PastFrames} past keys)");
            return sb.ToString();
        }

        private static void AppendList(StringBuilder sb, List<BakeGap> gaps, Func<BakeGap, string> describe)
        {
            const int Shown = 3;
            for (int i = 0; i < gaps.Count && i < Shown; i++)
            {
                if (i > 0) sb.Append(", ");
                sb.Append(describe(gaps[i]));
            }

            if (gaps.Count > Shown) sb.Append(", …");
        }
    }
}
