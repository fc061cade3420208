using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// A blend's frames once computed (<see cref="BlendCache.Get"/>): the character's poses from the first clip's
    /// pose at the span's start to the second clip's at its end, one per model frame, read at any point of the span by
    /// <see cref="Sample"/> — SLERP and LERP between the two model frames around it, as a clip on the rig is read
    /// (<see cref="MotionClipPoses"/>). Reading allocates nothing and never runs the network.
    /// </summary>
    public sealed class BlendFrames
    {
        private readonly MotionClip? _frames;
        private readonly MotionClipPoses? _poses;

        internal BlendFrames(BlendMode mode, CharacterRig rig, MotionClip? frames, string? warning)
        {
            Mode = mode;
            _frames = frames;
            _poses = frames == null ? null : new MotionClipPoses(rig.Name, rig, frames);
            Warning = warning;
        }

        /// <summary>Model, SLERP, or Timeline's crossfade (then there are no frames: <see cref="Sample"/> returns false).</summary>
        public BlendMode Mode { get; }

        /// <summary>Why the model's in-between is not what plays, said once when the blend was computed; null when it is.</summary>
        public string? Warning { get; }

        /// <summary>Model frames from the span's first pose to its last, both included (0 for a crossfade).</summary>
        public int FrameCount => _frames?.FrameCount ?? 0;

        /// <summary>The frames on the character's skeleton (<see cref="CharacterRig.Skeleton"/>), or null for a crossfade.</summary>
        public MotionClip? Motion => _frames;

        /// <summary>
        /// The pose at <paramref name="fraction"/> of the span (0: its start, 1: its end; clamped) as Unity's transforms
        /// take it (<see cref="CharacterPoseTrack.ReadUnityPose"/>). False, writing nothing, for a crossfade.
        /// </summary>
        public bool Sample(double fraction, Span<double> rootPosition, Span<double> localRotations)
        {
            if (_frames == null || _poses == null) return false;
            if (!(fraction > 0)) fraction = 0;
            if (fraction > 1) fraction = 1;
            _poses.SampleFrame(fraction * (_frames.FrameCount - 1), rootPosition, localRotations);
            return true;
        }
    }
}
