using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Evaluation.Baking;

namespace DeltaInterpolator.Cli.Scoring
{
    /// <summary><c>score --json</c>: every file's values, the totals per subject and over all files, each method beside its ratio to SLERP.</summary>
    internal static class ScoreReport
    {
        public static string Json(ScoreSheet sheet, IReadOnlyList<string> modelPaths, Core.Baking.KeySpacing every, IReadOnlyList<string>? acceptedReferencePoses = null)
        {
            int methods = sheet.Methods.Count;
            using var buffer = new MemoryStream();
            using (var w = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
            {
                // A file's or a total's errors: planted samples, the truth's skating, each method.
                void Errors(MethodErrors e)
                {
                    w.WriteNumber("foot_contact_samples", e.ContactSamples);
                    Skating("ground_truth_foot_skating", e.TruthFootSkating, e.ContactSamples);
                    w.WriteStartObject("methods");
                    for (int i = 0; i < methods; i++)
                    {
                        w.WriteStartObject(i < methods - 1 ? sheet.Methods[i] : "slerp");
                        w.WriteNumber("position_per_leg", e.PositionPerLeg[i]);
                        w.WriteNumber("l2q", e.L2Q[i]);
                        w.WriteNumber("position_vs_slerp", e.PositionRatio(i));
                        w.WriteNumber("l2q_vs_slerp", e.L2QRatio(i));
                        Skating("foot_skating", e.FootSkating[i], e.ContactSamples);
                        w.WriteEndObject();
                    }

                    w.WriteEndObject();
                }

                // A group's or the whole sheet's sums: frames, then the errors.
                void Totals(ScoreTotal t)
                {
                    w.WriteNumber("non_key_frames", t.Frames);
                    Errors(t.Errors);
                }

                void Skating(string key, double value, int contacts)
                {
                    if (contacts > 0 && double.IsFinite(value)) w.WriteNumber(key, value);
                    else w.WriteNull(key);
                }

                w.WriteStartObject();
                // A number of input frames as before; another unit as written on the command line ("15mf", "0.5s").
                if (every.Unit == Core.Baking.KeySpacingUnit.InputFrames) w.WriteNumber("every", every.Value);
                else w.WriteString("every", every.ToString());
                w.WriteStartArray("models");
                foreach (string p in modelPaths) w.WriteStringValue(p);
                w.WriteEndArray();
                // --accept-reference-pose: what each file's reference pose broke of the humanoid rule (absent when nothing).
                if (acceptedReferencePoses != null && acceptedReferencePoses.Count > 0)
                {
                    w.WriteStartArray("accepted_reference_poses");
                    foreach (string a in acceptedReferencePoses) w.WriteStringValue(a);
                    w.WriteEndArray();
                }

                w.WriteStartArray("files");
                foreach (ScoreRow r in sheet.Rows)
                {
                    w.WriteStartObject();
                    w.WriteString("file", r.File);
                    w.WriteString("group", r.Group);
                    w.WriteNumber("non_key_frames", r.Frames);
                    w.WriteNumber("leg_length", r.LegLength);
                    Errors(r.Errors);
                    w.WriteEndObject();
                }

                w.WriteEndArray();
                w.WriteStartObject("groups");
                foreach (var g in sheet.Groups())
                {
                    w.WriteStartObject(g.Key.Length == 0 ? "-" : g.Key);
                    Totals(sheet.Total(g.Value));
                    w.WriteEndObject();
                }

                w.WriteEndObject();
                ScoreTotal all = sheet.Total();
                w.WriteStartObject("total");
                w.WriteNumber("files", sheet.Rows.Count);
                Totals(all);
                w.WriteEndObject();
                w.WriteEndObject();
            }

            return Encoding.UTF8.GetString(buffer.ToArray()) + "\n";
        }
    }
}
