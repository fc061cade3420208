using System;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>What a character's request and recorded poses must satisfy before anything is built from them.</summary>
    internal static class RequestChecks
    {
        // Why a duration is longer than the model spans after P past frames (null: it fits).
        public static string? TooLong(ModelContract c, int pastFrames, double frameRate, double durationSeconds)
        {
            double frames = Math.Round(durationSeconds * frameRate);
            if (pastFrames + frames - 1 <= c.MaxFrameIndex) return null;
            double longest = (c.MaxFrameIndex - pastFrames + 1) / frameRate;
            return $"{durationSeconds:0.###} s is {frames:0} model frames; this model spans at most {longest:0.###} s after {pastFrames} past frames";
        }

        // The model's checks of a request of that length (missing frames as the player counts them): too long is an error, untrained gaps are warnings.
        public static ModelCheckReport Report(ModelContract c, int pastFrames, double frameRate, double durationSeconds, int missingFrames)
        {
            var report = new ModelCheckReport();
            string? tooLong = TooLong(c, pastFrames, frameRate, durationSeconds);
            if (tooLong != null)
            {
                report.Error(c.Source, tooLong, "expected a shorter transition; split it with an intermediate target");
                return report;
            }

            ModelChecks.Request(c, pastFrames, missingFrames, report);
            return report;
        }

        // A non-finite pose would reach the network's keys and show NaN on the character for the whole transition.
        public static void CheckFinite(ReadOnlySpan<double> root, ReadOnlySpan<double> rotations, string what, string rootName, string rotationsName)
        {
            string? problem = NonFinite(root, rotations, what);
            if (problem != null) throw new ArgumentException(problem, problem.Contains("root position") ? rootName : rotationsName);
        }

        /// <summary>What is not finite in a pose (root 3 values, rotations bones × 4), or null when every value is.</summary>
        public static string? NonFinite(ReadOnlySpan<double> root, ReadOnlySpan<double> rotations, string what)
        {
            for (int i = 0; i < root.Length; i++)
            {
                if (!double.IsFinite(root[i])) return $"the {what} has root position value {i} = {root[i]}; expected finite numbers";
            }

            for (int i = 0; i < rotations.Length; i++)
            {
                if (!double.IsFinite(rotations[i])) return $"the {what} has bone {i / 4}'s rotation value {i % 4} = {rotations[i]}; expected finite numbers";
            }

            return null;
        }
    }
}
