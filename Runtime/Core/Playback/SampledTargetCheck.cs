using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Holds a target pose the engine read one way (Unity: transform handles on the input stream of a humanoid clip, a
    /// path no Unity code demonstrates) against the same clip frame read the engine's canonical way (Unity:
    /// <c>AnimationClip.SampleAnimation</c> on a hidden copy of the rig): the bones' local rotations must agree within
    /// <see cref="ToleranceDegrees"/>. The root bone is left out (its place is the root motion's, not the clip's).
    /// </summary>
    public static class SampledTargetCheck
    {
        /// <summary>Largest difference (degrees) of a bone's local rotation that still agrees: float rounding and the humanoid muscle round trip.</summary>
        public const double ToleranceDegrees = 1.0;

        /// <summary>
        /// The bone (index, from 1) whose local rotation differs most between <paramref name="read"/> and
        /// <paramref name="reference"/> (bones × 4 values, w x y z), and by how many degrees.
        /// </summary>
        /// <exception cref="ArgumentException">The two poses have different lengths, or a length that is not bones × 4.</exception>
        public static (int Bone, double Degrees) LargestDifference(ReadOnlySpan<double> read, ReadOnlySpan<double> reference)
        {
            if (read.Length != reference.Length || read.Length % 4 != 0)
                throw new ArgumentException($"two poses of bones × 4 rotation values each, not {read.Length} and {reference.Length}", nameof(reference));
            int worst = -1;
            double largest = 0;
            for (int b = 1; b < read.Length / 4; b++)
            {
                double dot = Math.Abs(Quaternions.Dot(Quaternions.Normalize(QuaternionD.Read(read, 4 * b)), Quaternions.Normalize(QuaternionD.Read(reference, 4 * b))));
                double degrees = 2.0 * Math.Acos(Math.Min(1.0, dot)) * 180.0 / Math.PI;
                if (!(degrees <= largest)) { largest = degrees; worst = b; }
            }

            return (worst, largest);
        }

        /// <summary>
        /// A one-line warning when the two reads of <paramref name="clipName"/> at <paramref name="time"/> disagree by more
        /// than <see cref="ToleranceDegrees"/> (naming the bone), else null.
        /// </summary>
        public static string? Compare(ReadOnlySpan<double> read, ReadOnlySpan<double> reference, string clipName, double time, Func<int, string> boneName)
        {
            if (boneName == null) throw new ArgumentNullException(nameof(boneName));
            (int bone, double degrees) = LargestDifference(read, reference);
            if (bone < 0 || degrees <= ToleranceDegrees) return null;
            return FormattableString.Invariant(
                $"the target pose read from clip '{clipName}' at {time:0.###} s differs from AnimationClip.SampleAnimation's by {degrees:0.#}° at bone {boneName(bone)} (more than {ToleranceDegrees}°); transitions to this clip arrive on the read pose, which the engine evaluated differently");
        }
    }
}
