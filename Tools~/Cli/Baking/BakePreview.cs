using System.Collections.Generic;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Preview;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Baking
{
    /// <summary><c>--preview</c>/<c>--png</c> of a bake (and the demo's): the HTML player and contact sheet of ground truth, SLERP and the model on the input's skeleton.</summary>
    internal static class BakePreview
    {
        /// <summary>
        /// Before any work: --preview and --png (the contact sheet's actual path) are writable, not inputs,
        /// and differ from each other and from the other outputs.
        /// </summary>
        public static void CheckOutputs(string? previewPath, string? pngPath, string[] otherOutputs, bool force, params string?[] inputs)
        {
            if (pngPath != null && previewPath == null) throw new CliErrors.UsageException($"{pngPath}: --png without --preview; expected --preview OUT.html with it");
            if (previewPath == null) return;
            var taken = new List<string>();
            foreach (string o in otherOutputs) taken.Add(Path.GetFullPath(o));
            string html = OutputFile.Check(previewPath, force, inputs);
            if (taken.Contains(Path.GetFullPath(html))) throw new CliErrors.UsageException($"{previewPath}: the same file as another output; expected a different path for --preview");
            taken.Add(Path.GetFullPath(html));
            if (pngPath == null) return;
            // The PNG and the SVG written instead when Chromium fails: both checked now, not after the work.
            ContactSheet.CheckOutputs(pngPath, force, taken, inputs);
        }

        // Each track's planted feet by the contact rule foot skating scores with, on the ground truth's ground level.
        private static void MarkPlantedFeet(PreviewScene scene, MotionClip[] clips, FootRig feet)
        {
            IReadOnlyList<int> joints = feet.FootJoints;
            var positions = new double[clips.Length][];
            for (int t = 0; t < clips.Length; t++) positions[t] = FootSkating.FootPositions(clips[t], 0, clips[t].FrameCount, joints);
            double ground = FootSkating.GroundLevel(positions[0], joints.Count);
            for (int t = 0; t < clips.Length; t++)
            {
                scene.Tracks[t].MarkPlantedFeet(joints, FootSkating.Planted(positions[t], joints.Count, clips[t].FrameTime, ground, feet.LegLength));
            }
        }

        /// <summary>The HTML player (and contact sheet) of ground truth, SLERP and model over the baked frames, on the input's skeleton.</summary>
        public static void Write(BvhAnimation animation, BakeRun run, string htmlPath, string? pngPath, bool force)
        {
            int first = run.RigKeys[0];
            MotionClip model = run["Model"].OnRig;
            MotionClip truth = animation.Motion.Excerpt(first, model.FrameCount);
            var keys = new int[run.RigKeys.Count];
            for (int i = 0; i < keys.Length; i++) keys[i] = run.RigKeys[i] - first;
            string title = Path.GetFileName(animation.SourceName) + $", frames {first}–{run.RigKeys[keys.Length - 1]}";
            MotionClip[] clips = { truth, run["SLERP"].OnRig, model };
            PreviewScene scene = PreviewScene.FromClips(title, new[] { ("Ground truth", clips[0]), ("SLERP", clips[1]), ("Model", clips[2]) }, keys, 0);
            scene.FirstFrame = first;
            MarkPlantedFeet(scene, clips, BakeScores.Feet(run, truth.Skeleton));
            PreviewWriter.WriteHtml(scene, htmlPath);
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB): ground truth, SLERP and model, {2} frames, {3} keys", htmlPath, new FileInfo(htmlPath).Length / 1024.0, scene.FrameCount, keys.Length)));
            if (pngPath == null) return;
            string? fallback = null;
            string written = pngPath;
            AnsiConsole.Status().Start("Rasterising the contact sheet with headless Chromium...", _ => written = ContactSheet.Write(scene, pngPath, force, out fallback));
            AnsiConsole.MarkupLine(Markup.Escape(fallback ?? string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB)", written, new FileInfo(written).Length / 1024.0)));
        }
    }
}
