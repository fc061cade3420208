using System;
using System.IO;
using System.Text;
using System.Text.Json;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// The scene as the compact JSON the player reads: positions as integers of <see cref="SceneLayout.Quantum"/>,
    /// each value stored as its change from the previous frame (motion is smooth, so most changes are a
    /// few digits), errors as integers of the same quantum. The default encoder escapes '&lt;', so the JSON
    /// can sit inside a &lt;script&gt; element as it is.
    /// </summary>
    internal static class PlayerData
    {
        public static string Build(PreviewScene scene, SceneLayout layout)
        {
            using var buffer = new MemoryStream();
            using (var json = new Utf8JsonWriter(buffer))
            {
                json.WriteStartObject();
                json.WriteString("title", scene.Title);
                json.WriteNumber("fps", Math.Round(1.0 / scene.FrameTime, 6));
                json.WriteNumber("frames", scene.FrameCount);
                json.WriteStartArray("joints");
                foreach (string name in scene.JointNames) json.WriteStringValue(name);
                json.WriteEndArray();
                json.WriteStartArray("parents");
                foreach (int parent in scene.Parents) json.WriteNumberValue(parent);
                json.WriteEndArray();
                json.WriteStartArray("keys");
                foreach (int key in scene.KeyFrames) json.WriteNumberValue(key);
                json.WriteEndArray();
                json.WriteNumber("groundTruth", scene.GroundTruthTrack);
                json.WriteNumber("firstFrame", scene.FirstFrame);
                json.WriteNumber("bodyRoot", scene.BodyRoot);
                json.WriteStartArray("drawsBone");
                for (int j = 0; j < scene.JointCount; j++) json.WriteNumberValue(scene.DrawsBone(j) ? 1 : 0);
                json.WriteEndArray();
                if (scene.MetresPerUnit is double metres && metres > 0) json.WriteNumber("cmPerUnit", Math.Round(metres * 100, 9));
                json.WriteNumber("quantum", layout.Quantum);
                json.WriteNumber("height", Round(layout.Height, layout.Quantum));
                json.WriteNumber("floor", Round(layout.Floor, layout.Quantum));
                WriteVector(json, "travel", layout.Travel);
                json.WriteStartArray("tracks");
                for (int t = 0; t < scene.Tracks.Count; t++)
                {
                    PreviewTrack track = scene.Tracks[t];
                    json.WriteStartObject();
                    json.WriteString("name", track.Name);
                    json.WriteString("color", TrackColors.Of(scene, t));
                    json.WriteNumber("frames", track.FrameCount);
                    double[] offset = layout.OffsetOf(t, scene.Tracks.Count);
                    WriteVector(json, "offset", new[] { Round(offset[0], layout.Quantum), 0, Round(offset[2], layout.Quantum) });
                    WritePositions(json, track, layout.Quantum);
                    if (track.FootJoints != null && track.Planted != null)
                    {
                        // Planted foot joints: one bit mask per frame (bit k: FootJoints[k] planted).
                        json.WriteStartArray("footJoints");
                        foreach (int j in track.FootJoints) json.WriteNumberValue(j);
                        json.WriteEndArray();
                        json.WriteStartArray("planted");
                        int c = track.FootJoints.Length;
                        for (int f = 0; f < track.FrameCount; f++)
                        {
                            int mask = 0;
                            for (int k = 0; k < c; k++) if (track.Planted[f * c + k]) mask |= 1 << k;
                            json.WriteNumberValue(mask);
                        }

                        json.WriteEndArray();
                    }

                    if (scene.GroundTruthTrack >= 0 && t != scene.GroundTruthTrack)
                    {
                        json.WriteNumber("meanError", Round(scene.MeanErrorBetweenKeys(t), layout.Quantum));
                        json.WriteStartArray("errors");
                        foreach (double e in scene.ErrorPerFrame(t)) json.WriteNumberValue((long)Math.Round(e / layout.Quantum));
                        json.WriteEndArray();
                    }

                    json.WriteEndObject();
                }

                json.WriteEndArray();
                json.WriteEndObject();
            }

            return Encoding.UTF8.GetString(buffer.ToArray());
        }

        private static void WritePositions(Utf8JsonWriter json, PreviewTrack track, double quantum)
        {
            json.WriteStartArray("deltas");
            int stride = track.JointCount * 3;
            double[] p = track.GlobalPositions;
            var previous = new long[stride];
            for (int f = 0; f < track.FrameCount; f++)
            {
                for (int k = 0; k < stride; k++)
                {
                    long value = (long)Math.Round(p[f * stride + k] / quantum);
                    json.WriteNumberValue(value - previous[k]);
                    previous[k] = value;
                }
            }

            json.WriteEndArray();
        }

        private static void WriteVector(Utf8JsonWriter json, string name, double[] v)
        {
            json.WriteStartArray(name);
            foreach (double x in v) json.WriteNumberValue(Math.Round(x, 6));
            json.WriteEndArray();
        }

        // Decimal places of the quantum, so 0.1 + 0.2 style binary noise never reaches the file.
        private static double Round(double value, double quantum)
        {
            int decimals = Math.Max(0, Math.Min(15, (int)Math.Ceiling(-Math.Log10(quantum))));
            return Math.Round(value, decimals);
        }
    }
}
