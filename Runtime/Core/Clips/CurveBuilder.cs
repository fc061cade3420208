using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// Turns baked motion on a character's skeleton into the float curves of a Unity clip: per bone the local rotation
    /// as four quaternion curves (<c>m_LocalRotation.x/y/z/w</c>, Unity order) and for the root also the
    /// local position (<c>m_LocalPosition.x/y/z</c>), one key per frame with linear tangents, as Unity's transforms
    /// take them (<see cref="CharacterPoseTrack.ReadUnityPose"/>: Unity's space, the rig's armature and units).
    /// </summary>
    public static class CurveBuilder
    {
        /// <summary>Property names of the rotation curves, in Unity's component order.</summary>
        public static readonly IReadOnlyList<string> RotationProperties = new[] { "m_LocalRotation.x", "m_LocalRotation.y", "m_LocalRotation.z", "m_LocalRotation.w" };

        /// <summary>Property names of the root position curves.</summary>
        public static readonly IReadOnlyList<string> PositionProperties = new[] { "m_LocalPosition.x", "m_LocalPosition.y", "m_LocalPosition.z" };

        /// <summary>
        /// The curves of a generic clip from motion on a character's skeleton (e.g. <see cref="Workflows.MethodBake.OnRig"/>
        /// of <see cref="Workflows.CharacterBake"/>): every rig bone's <c>m_LocalRotation</c> and the root bone's
        /// <c>m_LocalPosition</c>, as Unity's transforms take them (<see cref="CharacterPoseTrack.ReadUnityPose"/>).
        /// </summary>
        /// <param name="rig">The character.</param>
        /// <param name="motion">Motion on <see cref="CharacterRig.Skeleton"/>.</param>
        /// <param name="bonePaths">Each bone's transform path under the animated GameObject, in <see cref="CharacterRig.BoneNames"/> order.</param>
        public static IReadOnlyList<ClipCurve> BuildCharacter(CharacterRig rig, MotionClip motion, IReadOnlyList<string> bonePaths)
        {
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            if (motion == null) throw new ArgumentNullException(nameof(motion));
            if (bonePaths == null) throw new ArgumentNullException(nameof(bonePaths));
            int n = rig.BoneNames.Count;
            if (bonePaths.Count != n) throw new ArgumentException($"expected one path per bone ({n}), got {bonePaths.Count}", nameof(bonePaths));
            int frames = motion.FrameCount;
            var times = new float[frames];
            for (int f = 0; f < frames; f++) times[f] = (float)(f * motion.FrameTime);
            var rotations = new float[4 * n][];
            for (int c = 0; c < rotations.Length; c++) rotations[c] = new float[frames];
            var root = new float[3][];
            for (int c = 0; c < 3; c++) root[c] = new float[frames];
            var p = new double[3];
            var q = new double[4 * n];
            var previous = new double[4 * n];
            for (int f = 0; f < frames; f++)
            {
                CharacterPoseTrack.ReadUnityPose(rig, motion, f, p, q);
                for (int b = 0; b < n; b++)
                {
                    // q and −q are one rotation, but curves interpolate components: stay in the previous key's hemisphere.
                    double dot = 0;
                    for (int c = 0; c < 4; c++) dot += q[4 * b + c] * previous[4 * b + c];
                    double sign = f > 0 && dot < 0 ? -1 : 1;
                    for (int c = 0; c < 4; c++) previous[4 * b + c] = sign * q[4 * b + c];
                    // Unity's component order: x, y, z, w.
                    for (int c = 0; c < 4; c++) rotations[4 * b + c][f] = (float)previous[4 * b + (c + 1) % 4];
                }

                for (int c = 0; c < 3; c++) root[c][f] = (float)p[c];
            }

            var curves = new List<ClipCurve>();
            for (int b = 0; b < n; b++)
            {
                for (int c = 0; c < 4; c++) curves.Add(ClipCurve.Create(bonePaths[b], RotationProperties[c], (float[])times.Clone(), rotations[4 * b + c]));
            }

            for (int c = 0; c < 3; c++) curves.Add(ClipCurve.Create(bonePaths[0], PositionProperties[c], (float[])times.Clone(), root[c]));
            return curves;
        }
    }
}
