using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// The component's foot locking on the legs the character is shown with (issue 29, item 4; issue 27, item 5): a
    /// character mapped through a <see cref="SkeletonPoseConverter"/> is locked on its own skeleton (the map's source,
    /// <see cref="FootRig.ForSource"/>), as bakes lock a retargeted rig, because rotations that hold a foot still on the
    /// model's legs make it slide on legs of other proportions; any other map (a character on the model's own
    /// skeleton, <see cref="NamePoseConverter"/>) is locked in the model's space. Each shown pose: model space → the
    /// character's skeleton → locked → the character's bones. Allocation-free after construction.
    /// </summary>
    internal sealed class TransitionFeet
    {
        private readonly IPoseConverter _map;
        private readonly SkeletonPoseConverter? _rig;
        private readonly double[] _startRoot = new double[3];
        private readonly double[] _startRotations;

        private TransitionFeet(IPoseConverter map, LiveFootLocker locker, SkeletonPoseConverter? rig)
        {
            _map = map;
            Locker = locker;
            _rig = rig;
            _startRotations = new double[4 * locker.Rig.Skeleton.JointCount];
        }

        /// <summary>The locker (on the character's skeleton, or the model's).</summary>
        public LiveFootLocker Locker { get; }

        /// <summary>The feet of a player showing <paramref name="model"/>'s poses through <paramref name="map"/>, or null when neither skeleton has legs the locker finds.</summary>
        public static TransitionFeet? For(IPoseConverter map, Skeleton model)
        {
            if (map is SkeletonPoseConverter rig)
            {
                try
                {
                    return new TransitionFeet(map, new LiveFootLocker(FootRig.ForSource(rig.Map)), rig);
                }
                catch (ArgumentException)
                {
                    // The character's legs are not chains the locker can solve: lock in the model's space below.
                }
            }

            return FootRig.HasModelLegs(model) ? new TransitionFeet(map, new LiveFootLocker(FootRig.ForModel(model)), null) : null;
        }

        /// <summary>A transition starts from key <paramref name="start"/> towards key <paramref name="target"/> of <paramref name="t"/> (model space).</summary>
        public void Begin(Transition t, int start, int target, double startTime, double targetTime)
        {
            int jr = 4 * t.Skeleton.JointCount;
            var startRoot = new ReadOnlySpan<double>(t.KeyRootPositions, 3 * start, 3);
            var startRotations = new ReadOnlySpan<double>(t.KeyLocalRotations, jr * start, jr);
            var targetRoot = new ReadOnlySpan<double>(t.KeyRootPositions, 3 * target, 3);
            var targetRotations = new ReadOnlySpan<double>(t.KeyLocalRotations, jr * target, jr);
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
        /// The pose shown at <paramref name="time"/> (model space) locked with the shown frame's <paramref name="contacts"/>
        /// (empty: labelled) and put on the character's bones (<paramref name="boneRoot"/>, <paramref name="boneRotations"/>).
        /// </summary>
        public void LockAndShow(double time, ReadOnlySpan<double> jointRoot, Span<double> jointRotations, ReadOnlySpan<float> contacts, double threshold, Span<double> boneRoot, Span<double> boneRotations)
        {
            if (_rig == null)
            {
                Locker.LockPose(time, jointRoot, jointRotations, contacts, threshold);
                _map.ToCharacter(jointRoot, jointRotations, boneRoot, boneRotations);
                return;
            }

            _rig.ToSource(jointRoot, jointRotations);
            Locker.LockPose(time, _rig.SourceRoot, _rig.SourceRotations, contacts, threshold);
            _rig.SourceToCharacter(boneRoot, boneRotations);
        }
    }
}
