using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// The component's foot locking on the legs the character is shown with (issue 29, item 4; issue 27, item 5): a
    /// character mapped through a <see cref="SkeletonPoseConverter"/> is locked on its own skeleton (the map's source,
    /// <see cref="FootRig.ForSource"/>), as bakes lock a retargeted rig, because rotations that hold a foot still on the
    /// model's legs make it slide on legs of other proportions; any other map (a character on the model's own
    /// skeleton, <see cref="NamePoseConverter"/>) is locked in the model's space. Each shown pose: model space → the
    /// character's skeleton → locked → the character's bones. Once every network frame of a transition is decoded, its
    /// whole span (the past keys, the frames, the target) goes onto the same skeleton and the locker plans its contacts
    /// over it (<see cref="LiveFootLocker.PlanSpan"/>). Allocation-free after the first transition of each shape.
    /// </summary>
    internal sealed class TransitionFeet
    {
        private readonly IPoseConverter _map;
        private readonly SkeletonPoseConverter? _rig;
        private readonly double[] _startRoot = new double[3];
        private readonly double[] _startRotations;
        private readonly double _frameTime;
        // The span clips and their keys, one per transition shape (P, n), reused.
        private readonly ShapeCache<PlannedSpan> _spans = new ShapeCache<PlannedSpan>();
        private readonly FootContacts _contacts = new FootContacts();
        private bool _planned;

        private TransitionFeet(IPoseConverter map, LiveFootLocker locker, SkeletonPoseConverter? rig, double frameRate)
        {
            _map = map;
            Locker = locker;
            _rig = rig;
            _startRotations = new double[4 * locker.Rig.Skeleton.JointCount];
            _frameTime = 1 / frameRate;
        }

        /// <summary>The locker (on the character's skeleton, or the model's).</summary>
        public LiveFootLocker Locker { get; }

        /// <summary>The feet of a player showing <paramref name="model"/>'s poses through <paramref name="map"/>, or null when neither skeleton has legs the locker finds.</summary>
        public static TransitionFeet? For(IPoseConverter map, Skeleton model, double frameRate)
        {
            if (map is SkeletonPoseConverter rig)
            {
                try
                {
                    return new TransitionFeet(map, new LiveFootLocker(FootRig.ForSource(rig.Map)), rig, frameRate);
                }
                catch (ArgumentException)
                {
                    // The character's legs are not chains the locker can solve: lock in the model's space below.
                }
            }

            return FootRig.HasModelLegs(model) ? new TransitionFeet(map, new LiveFootLocker(FootRig.ForModel(model)), null, frameRate) : null;
        }

        /// <summary>A transition starts from key <paramref name="start"/> towards key <paramref name="target"/> of <paramref name="t"/> (model space).</summary>
        public void Begin(Transition t, int start, int target, double startTime, double targetTime)
        {
            int jr = 4 * t.Skeleton.JointCount;
            var startRoot = new ReadOnlySpan<double>(t.KeyRootPositions, 3 * start, 3);
            var startRotations = new ReadOnlySpan<double>(t.KeyLocalRotations, jr * start, jr);
            var targetRoot = new ReadOnlySpan<double>(t.KeyRootPositions, 3 * target, 3);
            var targetRotations = new ReadOnlySpan<double>(t.KeyLocalRotations, jr * target, jr);
            _planned = false;
            if (_rig == null)
            {
                Locker.Begin(startRoot, startRotations, targetRoot, targetRotations, startTime, targetTime);
                return;
            }

            _rig.ToSource(startRoot, startRotations);
            _rig.SourceRoot.CopyTo(_startRoot);
            _rig.SourceRotations.CopyTo(_startRotations);
            _rig.ToSource(targetRoot, targetRotations);
            Locker.Begin(_startRoot, _startRotations, _rig.SourceRoot, _rig.SourceRotations, startTime, targetTime);
        }

        /// <summary>
        /// The pose shown at <paramref name="time"/> (model time <paramref name="a"/> + <paramref name="f"/> of
        /// <paramref name="request"/>, model space) locked with the shown frame's predicted contacts (none: labelled) and put
        /// on the character's bones (<paramref name="boneRoot"/>, <paramref name="boneRotations"/>); in the first frame
        /// that finds all of the request's frames decoded, its span is planned first.
        /// </summary>
        public void LockAndShow(double time, TransitionRequest request, int a, double f, ReadOnlySpan<double> jointRoot, Span<double> jointRotations, Span<double> boneRoot, Span<double> boneRotations)
        {
            Transition t = request.Transition;
            if (!_planned && Locker.IsActive && request.Decoded >= t.MissingFrames) Plan(t);
            ReadOnlySpan<float> contacts = request.ContactsOf(a + (f < 0.5 ? 0 : 1));
            if (_rig == null)
            {
                Locker.LockPose(time, jointRoot, jointRotations, contacts, t.ContactThreshold);
                _map.ToCharacter(jointRoot, jointRotations, boneRoot, boneRotations);
                return;
            }

            _rig.ToSource(jointRoot, jointRotations);
            Locker.LockPose(time, _rig.SourceRoot, _rig.SourceRotations, contacts, t.ContactThreshold);
            _rig.SourceToCharacter(boneRoot, boneRotations);
        }

        /// <summary>The request's whole span on the locker's skeleton — its past keys, the network's frames, its target — planned (keys: the past frames and the target).</summary>
        private void Plan(Transition t)
        {
            _planned = true;
            int past = t.PastFrames, n = t.MissingFrames, frames = past + n + 1;
            Skeleton s = Locker.Rig.Skeleton;
            PlannedSpan? span = _spans.Find(past, n);
            if (span == null)
            {
                var positions = new double[frames * 3 * s.JointCount];
                for (int i = 0; i < frames; i++) s.OffsetSpan.CopyTo(positions.AsSpan(i * 3 * s.JointCount));
                var keys = new int[past + 1];
                for (int k = 0; k < past; k++) keys[k] = k;
                keys[past] = frames - 1;
                span = _spans.Add(past, n, new PlannedSpan(new MotionClip(s, frames, _frameTime, positions, new double[frames * 4 * s.JointCount]), keys));
            }

            int jr = 4 * t.Skeleton.JointCount;
            for (int i = 0; i < frames; i++)
            {
                // Span frame i: past key i, missing frame i − past, or the target (key past).
                bool key = i < past || i == frames - 1;
                int at = key ? Math.Min(i, past) : i - past;
                var root = new ReadOnlySpan<double>(key ? t.KeyRootPositions : t.RootPositions, 3 * at, 3);
                var rotations = new ReadOnlySpan<double>(key ? t.KeyLocalRotations : t.LocalRotations, jr * at, jr);
                Span<double> toRoot = span.Clip.LocalPositions.AsSpan(span.Clip.PositionIndex(i, 0), 3);
                Span<double> toRotations = span.Clip.LocalRotations.AsSpan(span.Clip.RotationIndex(i, 0), 4 * s.JointCount);
                if (_rig == null)
                {
                    root.CopyTo(toRoot);
                    rotations.CopyTo(toRotations);
                    continue;
                }

                _rig.ToSource(root, rotations);
                _rig.SourceRoot.CopyTo(toRoot);
                _rig.SourceRotations.CopyTo(toRotations);
            }

            FootContacts? contacts = null;
            if (t.HasFootContacts)
            {
                _contacts.Clear(frames);
                _contacts.SetPredicted(past, n, t.FootContacts, t.ContactThreshold);
                contacts = _contacts;
            }

            Locker.PlanSpan(span.Clip, span.Keys, span.Keys.Length - 2, contacts);
        }

        /// <summary>A transition shape's span on the locker's skeleton and its key frames (the past keys and the target).</summary>
        private sealed record PlannedSpan(MotionClip Clip, int[] Keys);
    }
}
