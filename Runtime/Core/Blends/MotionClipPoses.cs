using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// A clip on a character's own skeleton (<see cref="CharacterRig.Skeleton"/>, e.g. an imported BVH) as
    /// <see cref="IClipPoses"/>: frames SLERPed as <see cref="MotionResampler.Sample"/> reads them, turned into Unity's
    /// transforms by <see cref="CharacterPoseTrack.ReadUnityPose"/>. What the tests and the command line play on a
    /// track where Unity would sample an AnimationClip. Allocation-free per sample.
    /// </summary>
    public sealed class MotionClipPoses : IClipPoses
    {
        private readonly CharacterRig _rig;
        private readonly MotionClip _motion;
        private readonly MotionClip _frame;

        /// <summary>Poses of <paramref name="motion"/> on <paramref name="rig"/>.</summary>
        /// <exception cref="ArgumentException">The motion's joints are not the rig's bones (<c>motion</c> named).</exception>
        public MotionClipPoses(string name, CharacterRig rig, MotionClip motion)
        {
            Name = name ?? throw new ArgumentNullException(nameof(name));
            _rig = rig ?? throw new ArgumentNullException(nameof(rig));
            _motion = motion ?? throw new ArgumentNullException(nameof(motion));
            if (motion.Skeleton.JointCount != rig.Skeleton.JointCount)
            {
                throw new ArgumentException($"{name}: the motion has {motion.Skeleton.JointCount} joints; expected the {rig.Skeleton.JointCount} bones of {rig.Name}", nameof(motion));
            }

            _frame = MotionClip.CreateRestPose(motion.Skeleton, 1, motion.FrameTime);
        }

        /// <inheritdoc />
        public string Name { get; }

        /// <summary>The animation's length in seconds (first to last frame).</summary>
        public double Length => (_motion.FrameCount - 1) * _motion.FrameTime;

        /// <inheritdoc />
        public void Sample(double time, Span<double> rootPosition, Span<double> localRotations) => SampleFrame(time / _motion.FrameTime, rootPosition, localRotations);

        /// <summary>The pose at frame <paramref name="frame"/> (fractional: SLERP and LERP between the frames around it) as Unity's transforms take it.</summary>
        internal void SampleFrame(double frame, Span<double> rootPosition, Span<double> localRotations)
        {
            MotionResampler.Sample(_motion, frame, _frame.LocalPositions, _frame.LocalRotations);
            CharacterPoseTrack.ReadUnityPose(_rig, _frame, 0, rootPosition, localRotations);
        }
    }
}
