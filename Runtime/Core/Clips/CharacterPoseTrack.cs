using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// Key poses of a character as Unity holds them (the root bone's local position in the armature, every
    /// rig bone's local rotation (w, x, y, z), left-handed), written into a <see cref="MotionClip"/> on the
    /// character's own skeleton (<see cref="CharacterRig.Skeleton"/>: right-handed, armature applied to the
    /// root, offsets in the character's units) at their frame indices; and the way back,
    /// <see cref="ReadUnityPose"/>. The same conversion as the component's <see cref="SkeletonPoseConverter"/>
    /// before and after its <see cref="SkeletonMap"/>, so the editor baker and the component see one rig.
    /// Frames without a key keep the reference pose until a bake fills them.
    /// </summary>
    public sealed class CharacterPoseTrack
    {
        private readonly SortedSet<int> _keys = new SortedSet<int>();

        /// <summary>A track of <paramref name="frameCount"/> frames of <paramref name="rig"/>, <paramref name="frameTime"/> seconds apart.</summary>
        /// <exception cref="ArgumentOutOfRangeException">No frames, or a frame time that is not a positive number.</exception>
        public CharacterPoseTrack(CharacterRig rig, int frameCount, double frameTime)
        {
            Rig = rig ?? throw new ArgumentNullException(nameof(rig));
            if (frameCount < 1) throw new ArgumentOutOfRangeException(nameof(frameCount), frameCount, "a track needs at least one frame");
            if (!(frameTime > 0) || double.IsInfinity(frameTime)) throw new ArgumentOutOfRangeException(nameof(frameTime), frameTime, "expected a positive frame time (seconds)");
            Motion = MotionClip.CreateRestPose(rig.Skeleton, frameCount, frameTime);
            ReferencePose reference = rig.ReferencePose;
            int n = rig.Skeleton.JointCount;
            for (int f = 0; f < frameCount; f++)
            {
                for (int i = 0; i < 4 * n; i++) Motion.LocalRotations[Motion.RotationIndex(f, 0) + i] = reference.LocalRotations[i];
            }
        }

        /// <summary>The character.</summary>
        public CharacterRig Rig { get; }

        /// <summary>The motion on <see cref="CharacterRig.Skeleton"/>: key frames set, the others in the reference pose.</summary>
        public MotionClip Motion { get; }

        /// <summary>Frames set by <see cref="SetUnityPose"/>, ascending.</summary>
        public IReadOnlyCollection<int> KeyFrames => _keys;

        /// <summary>Sets frame <paramref name="frame"/> from what Unity's transforms hold.</summary>
        /// <param name="frame">Frame index in the track.</param>
        /// <param name="rootPosition">The root bone's <c>localPosition</c> (x, y, z; in the armature, its units).</param>
        /// <param name="localRotations">Every rig bone's <c>localRotation</c> as (w, x, y, z), bones × 4, in <see cref="CharacterRig.BoneNames"/> order.</param>
        /// <exception cref="ArgumentOutOfRangeException">The frame is outside the track.</exception>
        /// <exception cref="ArgumentException">Not one rotation per bone, or a rotation that is zero or not finite (bone and frame named).</exception>
        public void SetUnityPose(int frame, ReadOnlySpan<double> rootPosition, ReadOnlySpan<double> localRotations)
        {
            int n = Rig.Skeleton.JointCount;
            if ((uint)frame >= (uint)Motion.FrameCount) throw new ArgumentOutOfRangeException(nameof(frame), frame, $"frame {frame} is outside the track's {Motion.FrameCount} frames");
            if (rootPosition.Length != 3) throw new ArgumentException("expected the root position as 3 values", nameof(rootPosition));
            if (localRotations.Length != 4 * n) throw new ArgumentException($"expected {n} bones × 4 = {4 * n} rotation values, got {localRotations.Length}", nameof(localRotations));
            double[] rotations = Motion.LocalRotations;
            int at = Motion.RotationIndex(frame, 0);
            for (int b = 0; b < n; b++)
            {
                QuaternionD q = QuaternionD.Read(localRotations, 4 * b);
                double length = q.Length;
                if (!(length > 1e-6) || double.IsInfinity(length))
                {
                    throw new ArgumentException($"{Rig.Name}: bone '{Rig.BoneNames[b]}' has a rotation of length {length} at frame {frame}; expected a unit quaternion (w, x, y, z)", nameof(localRotations));
                }

                if (b == 0) q = Rig.Armature.RotationToParent(q);
                Quaternions.Normalize(Handedness.RotationFromUnity(q)).Write(rotations, at + 4 * b);
            }

            Vector3D root = Handedness.PositionFromUnity(Rig.Armature.PointToParent(Vector3D.Read(rootPosition, 0)));
            root.Write(Motion.LocalPositions, Motion.PositionIndex(frame, 0));
            _keys.Add(frame);
        }

        /// <summary>
        /// Frame <paramref name="frame"/> of <paramref name="motion"/> (on <paramref name="rig"/>'s skeleton, e.g. a
        /// bake's <c>OnRig</c>) as Unity's transforms take it: the root bone's local position and every bone's
        /// local rotation (w, x, y, z).
        /// </summary>
        public static void ReadUnityPose(CharacterRig rig, MotionClip motion, int frame, Span<double> rootPosition, Span<double> localRotations)
        {
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (motion == null) throw new ArgumentNullException(nameof(motion));
            int n = rig.Skeleton.JointCount;
            if (motion.Skeleton.JointCount != n) throw new ArgumentException($"the motion has {motion.Skeleton.JointCount} joints; {rig.Name} has {n} bones", nameof(motion));
            if ((uint)frame >= (uint)motion.FrameCount) throw new ArgumentOutOfRangeException(nameof(frame), frame, $"frame {frame} is outside the motion's {motion.FrameCount} frames");
            if (rootPosition.Length != 3 || localRotations.Length != 4 * n) throw new ArgumentException($"expected 3 root values and {4 * n} rotation values");
            int at = motion.RotationIndex(frame, 0);
            for (int b = 0; b < n; b++)
            {
                QuaternionD q = Handedness.RotationToUnity(Quaternions.Normalize(QuaternionD.Read(motion.LocalRotations, at + 4 * b)));
                if (b == 0) q = rig.Armature.RotationFromParent(q);
                q.Write(localRotations, 4 * b);
            }

            rig.Armature.PointFromParent(Handedness.PositionToUnity(Vector3D.Read(motion.LocalPositions, motion.PositionIndex(frame, 0)))).Write(rootPosition, 0);
        }
    }
}
