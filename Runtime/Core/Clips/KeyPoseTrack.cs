using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// Key poses sampled from a character in Unity, written into a model-space <see cref="MotionClip"/>
    /// at their frame indices: local rotations given in Unity's (x, y, z, w) order and left-handed space
    /// become (w, x, y, z) right-handed through <see cref="Handedness"/>, and the root position is
    /// converted from metres to the model's data units. Frames without a key keep the rest pose until a
    /// baker fills them.
    /// </summary>
    /// <remarks>
    /// The character's bones must be the model's skeleton (same joints, same rest conventions, e.g. the
    /// BVH the model was trained on, imported into Unity); retargeting other rigs is the skeleton map's job.
    /// </remarks>
    public sealed class KeyPoseTrack
    {
        private readonly SortedSet<int> _keys = new SortedSet<int>();
        private readonly double _metresPerDataUnit;

        /// <summary>Creates a track of <paramref name="frameCount"/> frames in the rest pose.</summary>
        /// <param name="skeleton">The model's skeleton.</param>
        /// <param name="frameCount">Frames of the clip to bake.</param>
        /// <param name="frameRate">The model's frame rate.</param>
        /// <param name="metresPerDataUnit">Unity metres per data unit (the contract's unit scale, 0.01 for centimetre data).</param>
        public KeyPoseTrack(Skeleton skeleton, int frameCount, double frameRate, double metresPerDataUnit)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            if (frameCount < 1) throw new ArgumentOutOfRangeException(nameof(frameCount), "a track needs at least one frame");
            if (!(frameRate > 0) || double.IsInfinity(frameRate)) throw new ArgumentOutOfRangeException(nameof(frameRate), "the frame rate must be a positive number");
            if (!(metresPerDataUnit > 0) || double.IsInfinity(metresPerDataUnit)) throw new ArgumentOutOfRangeException(nameof(metresPerDataUnit), "the unit scale must be a positive number");
            _metresPerDataUnit = metresPerDataUnit;
            Motion = MotionClip.CreateRestPose(skeleton, frameCount, 1.0 / frameRate);
        }

        /// <summary>The model-space motion: key frames set, the rest in the rest pose.</summary>
        public MotionClip Motion { get; }

        /// <summary>Frames set by <see cref="SetUnityPose"/>, ascending.</summary>
        public IReadOnlyCollection<int> KeyFrames => _keys;

        /// <summary>
        /// Sets frame <paramref name="frame"/> from a Unity pose.
        /// </summary>
        /// <param name="frame">Frame index in the track.</param>
        /// <param name="localRotationsXyzw">Every joint's <c>Transform.localRotation</c> in Unity order, joints × 4.</param>
        /// <param name="rootX">The root's <c>localPosition.x</c> (metres).</param>
        /// <param name="rootY">The root's <c>localPosition.y</c>.</param>
        /// <param name="rootZ">The root's <c>localPosition.z</c>.</param>
        public void SetUnityPose(int frame, ReadOnlySpan<float> localRotationsXyzw, float rootX, float rootY, float rootZ)
        {
            int jc = Motion.Skeleton.JointCount;
            if ((uint)frame >= (uint)Motion.FrameCount) throw new ArgumentOutOfRangeException(nameof(frame), $"frame {frame} is outside the track's {Motion.FrameCount} frames");
            if (localRotationsXyzw.Length != jc * 4) throw new ArgumentException($"expected {jc} joints × 4 = {jc * 4} values", nameof(localRotationsXyzw));
            double[] rotations = Motion.LocalRotations;
            for (int j = 0; j < jc; j++)
            {
                var unity = new QuaternionD(localRotationsXyzw[4 * j + 3], localRotationsXyzw[4 * j], localRotationsXyzw[4 * j + 1], localRotationsXyzw[4 * j + 2]);
                Quaternions.Normalize(Handedness.RotationFromUnity(unity)).Write(rotations, Motion.RotationIndex(frame, j));
            }

            Vector3D root = Handedness.PositionFromUnity(new Vector3D(rootX, rootY, rootZ));
            ((1.0 / _metresPerDataUnit) * root).Write(Motion.LocalPositions, Motion.PositionIndex(frame, 0));
            _keys.Add(frame);
        }
    }
}
