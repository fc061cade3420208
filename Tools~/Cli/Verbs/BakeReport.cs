using System;
using System.IO;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Evaluation.Baking;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// <c>bake --json</c>: one file's scores per method, in the units users compare across files and rigs
    /// (mean joint position error in file units and ÷ the file's leg length, L2Q, L2P where statistics apply,
    /// foot skating in leg lengths per second beside the ground truth's own)
    /// with the non-key frame count, so sums over files weight every non-key frame equally (what
    /// <c>score</c> adds up).
    /// </summary>
    internal static class BakeReport
    {
        /// <summary>Report format version (bump when a field changes meaning).</summary>
        public const int Version = 1;

        public static string Json(string input, BvhAnimation animation, int[] inputKeys, BakeOutcome outcome, ModelContract contract, string modelPath,
            BakeAccuracy model, BakeAccuracy slerp, BakeFeet.Scores skating, bool feetLocked)
        {
            double leg = BakeInput.LegLength(outcome.Seam, contract, animation);
            using var buffer = new MemoryStream();
            using (var w = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
            {
                w.WriteStartObject();
                w.WriteNumber("version", Version);
                w.WriteString("file", input);
                w.WriteNumber("frames", animation.Motion.FrameCount);
                w.WriteNumber("fps", Math.Round(1.0 / animation.Motion.FrameTime, 6));
                w.WriteStartArray("keys");
                foreach (int k in inputKeys) w.WriteNumberValue(k);
                w.WriteEndArray();
                w.WriteNumber("non_key_frames", model.Frames);
                w.WriteNumber("leg_length", leg);
                w.WriteString("retargeting", outcome.Seam.Description);
                w.WriteString("feet", feetLocked ? "lock" : "off");
                w.WriteNumber("foot_contact_samples", skating.Truth.ContactSamples);
                Skating(w, "ground_truth_foot_skating", skating.Truth);
                w.WriteStartObject("methods");
                Method(w, "model", contract.Name, modelPath, model, leg, outcome.ModelSeconds, skating.Model);
                Method(w, "slerp", "SLERP", null, slerp, leg, outcome.SlerpSeconds, skating.Slerp);
                w.WriteEndObject();
                w.WriteEndObject();
            }

            return Encoding.UTF8.GetString(buffer.ToArray()) + "\n";
        }

        /// <summary>Foot skating in leg lengths per second, or null where the truth has no planted foot on a filled frame.</summary>
        private static void Skating(Utf8JsonWriter w, string key, FootSkating s)
        {
            if (double.IsFinite(s.MeanSpeed)) w.WriteNumber(key, s.MeanSpeed);
            else w.WriteNull(key);
        }

        private static void Method(Utf8JsonWriter w, string key, string name, string? path, BakeAccuracy a, double leg, double seconds, FootSkating skating)
        {
            if (!double.IsFinite(a.MeanPositionError) || !double.IsFinite(a.L2Q))
            {
                throw new CliErrors.UsageException($"{name}: the bake gave non-finite errors; expected finite motion values in the input");
            }

            w.WriteStartObject(key);
            w.WriteString("name", name);
            if (path != null) w.WriteString("path", path);
            w.WriteNumber("mean_position_error", a.MeanPositionError);
            w.WriteNumber("mean_position_error_per_leg", a.MeanPositionError / leg);
            w.WriteNumber("l2q", a.L2Q);
            if (double.IsFinite(a.L2P)) w.WriteNumber("l2p", a.L2P);
            else w.WriteNull("l2p");
            Skating(w, "foot_skating", skating);
            w.WriteNumber("seconds", seconds);
            w.WriteEndObject();
        }
    }
}
