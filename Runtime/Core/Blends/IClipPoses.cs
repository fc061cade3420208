using System;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// A clip as poses of one character: what its bones hold at an animation time, as Unity's transforms hold them
    /// (the root bone's local position, every rig bone's local rotation (w, x, y, z), left-handed, in
    /// <see cref="Characters.CharacterRig.BoneNames"/> order; what <see cref="Clips.CharacterPoseTrack.SetUnityPose"/>
    /// takes). The Unity layer samples an AnimationClip; <see cref="MotionClipPoses"/> reads a Core clip.
    /// </summary>
    public interface IClipPoses
    {
        /// <summary>A name for warnings (the clip's).</summary>
        string Name { get; }

        /// <summary>Writes the pose at <paramref name="time"/> seconds of the animation.</summary>
        void Sample(double time, Span<double> rootPosition, Span<double> localRotations);
    }
}
