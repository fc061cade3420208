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

        /// <summary>
        /// The model's track marks the contacts it predicted (issue 29) where it filled a frame, on the rig's frames
        /// (nearest in time), and the measure's rule on its keys; false when the model predicts none.
        /// </summary>
        private static bool MarkPredictedFeet(PreviewScene scene, int track, BakeRun run, MotionClip onRig, FootRig feet)
        {
            MethodBake model = run["Model"];
            if (!model.Contacts.AnyPredicted) return false;
            var contacts = new FootContacts();
            model.Contacts.ResampleInto(contacts, onRig.FrameCount, onRig.FrameTime, model.OnModel.FrameTime,
                run.RigKeys[0] * onRig.FrameTime - run.ModelKeys[0] * model.OnModel.FrameTime);
            PreviewTrack t = scene.Tracks[track];
            IReadOnlyList<int> joints = feet.FootJoints;
            bool[] planted = t.Planted!;
            for (int f = 0; f < onRig.FrameCount; f++)
            {
                if (!contacts.IsPredicted(f)) continue;
                for (int c = 0, k = 0; c < FootContacts.ChannelCount; c++)
                {
                    if (c % 2 == 1 && !feet[c / 2].HasToe) continue;
                    planted[f * joints.Count + k++] = contacts.IsPlanted(f, c);
                }
            }

            t.MarkPlantedFeet(joints, planted);
            return true;
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
            FootRig feet = BakeScores.Feet(run, truth.Skeleton);
            MarkPlantedFeet(scene, clips, feet);
            bool predicted = MarkPredictedFeet(scene, 2, run, model, feet);
            PreviewWriter.WriteHtml(scene, htmlPath);
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB): ground truth, SLERP and model, {2} frames, {3} keys{4}", htmlPath, new FileInfo(htmlPath).Length / 1024.0, scene.FrameCount, keys.Length,
                predicted ? "; the model's footprints are the contacts it predicted" : "")));
            if (pngPath == null) return;
            string? fallback = null;
            string written = pngPath;
            AnsiConsole.Status().Start("Rasterising the contact sheet with headless Chromium...", _ => written = ContactSheet.Write(scene, pngPath, force, out fallback));
            AnsiConsole.MarkupLine(Markup.Escape(fallback ?? string.Format(CultureInfo.InvariantCulture, "wrote {0} ({1:0} KB)", written, new FileInfo(written).Length / 1024.0)));
        }
    }
}
