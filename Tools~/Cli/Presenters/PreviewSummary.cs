using System;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Preview;

namespace DeltaInterpolator.Cli.Presenters
{
    /// <summary>
    /// What <c>inbetween preview</c> wrote, on stdout: the page (tracks, frames, keys), each track's error
    /// against the ground truth, and the contact sheet. File and track names come from the user and the
    /// files, so every line goes through <see cref="TerminalText"/> (no raw escapes, no forged lines).
    /// </summary>
    internal static class PreviewSummary
    {
        /// <summary>The page line, then one error line per track when the scene has a ground truth.</summary>
        public static void Page(PreviewScene scene, string htmlPath)
        {
            SafeLine(string.Format(
                CultureInfo.InvariantCulture,
                "wrote {0} ({1:0} KB): {2} track{6}, {3} frames at {4:0.##} fps, {5} key frames",
                htmlPath,
                new FileInfo(htmlPath).Length / 1024.0,
                scene.Tracks.Count,
                scene.FrameCount,
                1 / scene.FrameTime,
                scene.KeyFrames.Count,
                scene.Tracks.Count == 1 ? "" : "s"));
            if (scene.UpAxisDescription.Length > 0) SafeLine("  " + scene.UpAxisDescription);
            if (scene.GroundTruthTrack < 0) return;
            for (int t = 0; t < scene.Tracks.Count; t++)
            {
                if (t == scene.GroundTruthTrack) continue;
                SafeLine(string.Format(
                    CultureInfo.InvariantCulture,
                    "  {0}: mean joint position error {1:0.###} (data units) {2}",
                    scene.Tracks[t].Name,
                    scene.MeanErrorBetweenKeys(t),
                    scene.KeyFrames.Count > 0 ? "on frames between keys" : "over all frames"));
            }
        }

        /// <summary>The contact sheet line: the file written, or why an SVG was written instead.</summary>
        public static void Sheet(string written, string? fallback)
        {
            SafeLine(fallback ?? string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB)", written, new FileInfo(written).Length / 1024.0));
        }

        private static void SafeLine(string line) => Console.WriteLine(TerminalText.Safe(line, TerminalText.LineLength));
    }
}
