using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// The curves of a humanoid clip (bound to the Animator, path ""): the body's position and rotation
    /// (<c>RootT.*</c>, <c>RootQ.*</c>) and one curve per muscle, named as Unity's clips name them. A humanoid
    /// Animator plays only these; <c>m_LocalRotation</c> curves of its bones are ignored by its avatar.
    /// </summary>
    public static class HumanoidCurves
    {
        /// <summary>The body position curves, (x, y, z).</summary>
        public static readonly IReadOnlyList<string> RootPositionProperties = new[] { "RootT.x", "RootT.y", "RootT.z" };

        /// <summary>The body rotation curves, in Unity's component order (x, y, z, w).</summary>
        public static readonly IReadOnlyList<string> RootRotationProperties = new[] { "RootQ.x", "RootQ.y", "RootQ.z", "RootQ.w" };

        private static readonly string[] Fingers = { "Thumb", "Index", "Middle", "Ring", "Little" };

        /// <summary>
        /// A muscle's curve property from its <c>HumanTrait.MuscleName</c>: the same, except finger muscles, which
        /// clips name by hand ("Left Index 1 Stretched" → "LeftHand.Index.1 Stretched", "Right Thumb Spread" →
        /// "RightHand.Thumb.Spread").
        /// </summary>
        public static string MuscleProperty(string muscleName)
        {
            if (muscleName == null) throw new ArgumentNullException(nameof(muscleName));
            foreach (string side in new[] { "Left", "Right" })
            {
                foreach (string finger in Fingers)
                {
                    string prefix = side + " " + finger + " ";
                    if (muscleName.StartsWith(prefix, StringComparison.Ordinal))
                    {
                        return side + "Hand." + finger + "." + muscleName.Substring(prefix.Length);
                    }
                }
            }

            return muscleName;
        }

        /// <summary>True for a humanoid clip's pose curve: the body's position or rotation, or one of <paramref name="muscleProperties"/>.</summary>
        /// <param name="propertyName">A curve's property name as Unity stores it.</param>
        /// <param name="muscleProperties">Every muscle's property (<see cref="MuscleProperty"/> of each <c>HumanTrait.MuscleName</c>).</param>
        public static bool IsPoseProperty(string propertyName, ICollection<string> muscleProperties)
        {
            if (string.IsNullOrEmpty(propertyName)) return false;
            foreach (string p in RootPositionProperties)
            {
                if (p == propertyName) return true;
            }

            foreach (string p in RootRotationProperties)
            {
                if (p == propertyName) return true;
            }

            return muscleProperties != null && muscleProperties.Contains(propertyName);
        }

        /// <summary>
        /// The curves of a humanoid clip from per-frame human poses (what <c>HumanPoseHandler.GetHumanPose</c> gives),
        /// one key per frame with linear tangents; the body rotation kept in one hemisphere from key to key.
        /// </summary>
        /// <param name="muscleNames"><c>HumanTrait.MuscleName</c>.</param>
        /// <param name="frameTime">Seconds between frames.</param>
        /// <param name="bodyPositions">Frames × 3: <c>HumanPose.bodyPosition</c>.</param>
        /// <param name="bodyRotations">Frames × 4, (x, y, z, w): <c>HumanPose.bodyRotation</c>.</param>
        /// <param name="muscles">Frames × muscles: <c>HumanPose.muscles</c>.</param>
        /// <returns>RootT, RootQ, then one curve per muscle, each with path "".</returns>
        public static IReadOnlyList<ClipCurve> Build(IReadOnlyList<string> muscleNames, double frameTime, float[] bodyPositions, float[] bodyRotations, float[] muscles)
        {
            if (muscleNames == null) throw new ArgumentNullException(nameof(muscleNames));
            if (bodyPositions == null || bodyRotations == null || muscles == null) throw new ArgumentNullException(bodyPositions == null ? nameof(bodyPositions) : bodyRotations == null ? nameof(bodyRotations) : nameof(muscles));
            if (!(frameTime > 0) || double.IsInfinity(frameTime)) throw new ArgumentOutOfRangeException(nameof(frameTime), frameTime, "expected a positive frame time (seconds)");
            int frames = bodyPositions.Length / 3;
            int m = muscleNames.Count;
            if (bodyPositions.Length != 3 * frames || bodyRotations.Length != 4 * frames || muscles.Length != m * frames)
            {
                throw new ArgumentException($"expected frames × 3 positions, frames × 4 rotations and frames × {m} muscles; got {bodyPositions.Length}, {bodyRotations.Length} and {muscles.Length}");
            }

            var times = new float[frames];
            for (int f = 0; f < frames; f++) times[f] = (float)(f * frameTime);
            var curves = new List<ClipCurve>();
            for (int c = 0; c < 3; c++) curves.Add(ClipCurve.Create("", RootPositionProperties[c], (float[])times.Clone(), Column(bodyPositions, 3, c, frames)));

            var rotations = (float[])bodyRotations.Clone();
            for (int f = 1; f < frames; f++)
            {
                float dot = 0;
                for (int c = 0; c < 4; c++) dot += rotations[4 * f + c] * rotations[4 * (f - 1) + c];
                if (dot < 0)
                {
                    for (int c = 0; c < 4; c++) rotations[4 * f + c] = -rotations[4 * f + c];
                }
            }

            for (int c = 0; c < 4; c++) curves.Add(ClipCurve.Create("", RootRotationProperties[c], (float[])times.Clone(), Column(rotations, 4, c, frames)));
            for (int i = 0; i < m; i++) curves.Add(ClipCurve.Create("", MuscleProperty(muscleNames[i]), (float[])times.Clone(), Column(muscles, m, i, frames)));
            return curves;
        }

        private static float[] Column(float[] values, int stride, int column, int frames)
        {
            var result = new float[frames];
            for (int f = 0; f < frames; f++) result[f] = values[f * stride + column];
            return result;
        }
    }
}
