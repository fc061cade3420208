using System;
using System.IO;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Evaluation.Baking;

namespace DeltaInterpolator.Cli.Baking
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

        public static string Json(string input, BvhAnimation animation, BakeRun run, BakeScores scores, ModelContract contract, string modelPath, bool feetLocked)
        {
            double leg = scores.LegLength;
            MethodScore model = scores["Model"], slerp = scores["SLERP"];
            using var buffer = new MemoryStream();
            using (var w = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
            {
                w.WriteStartObject();
                w.WriteNumber("version", Version);
                w.WriteString("file", input);
                w.WriteNumber("frames", animation.Motion.FrameCount);
                w.WriteNumber("fps", Math.Round(1.0 / animation.Motion.FrameTime, 6));
                w.WriteStartArray("keys");
                foreach (int k in run.RigKeys) w.WriteNumberValue(k);
                w.WriteEndArray();
                w.WriteNumber("non_key_frames", model.Accuracy.Frames);
                w.WriteNumber("leg_length", leg);
                w.WriteString("retargeting", run.Rig.Description);
                w.WriteString("feet", feetLocked ? "lock" : "off");
                // Where the model's locker took its contacts from (issue 29): the network's own where it predicts them; SLERP's are always labelled.
                if (feetLocked) w.WriteString("model_contacts", contract.HasFootContacts ? "predicted" : "labelled");
                w.WriteNumber("foot_contact_samples", scores.TruthSkating.ContactSamples);
                Skating(w, "ground_truth_foot_skating", scores.TruthSkating);
                w.WriteStartObject("methods");
                Method(w, "model", contract.Name, modelPath, model, leg, run["Model"].Seconds);
                Method(w, "slerp", "SLERP", null, slerp, leg, run["SLERP"].Seconds);
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

        private static void Method(Utf8JsonWriter w, string key, string name, string? path, MethodScore score, double leg, double seconds)
        {
            BakeAccuracy a = score.Accuracy;
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
            Skating(w, "foot_skating", score.Skating);
            w.WriteNumber("seconds", seconds);
            w.WriteEndObject();
        }
    }
}
