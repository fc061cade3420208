using System;
using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Cli.Verbs;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Retargeting
{
    /// <summary>What <c>retarget</c> prints: input, reference pose, joint map, made-up and unmapped joints, root scale, target, frames.</summary>
    internal static class RetargetSummary
    {
        public static void Print(string input, BvhAnimation source, SkeletonMap toModel, SkeletonMap? fromModel, int? referenceFrame, bool scaleGiven,
            int? fromFrame, double? inputFps, BvhAnimation result, string output, string target, double seconds)
        {
            var table = new Table().Border(TableBorder.Rounded).HideHeaders();
            table.AddColumn("");
            table.AddColumn("");
            MotionClip inClip = source.Motion, outClip = result.Motion;
            table.AddRow("Input", Markup.Escape($"{input}: {source.Skeleton.JointCount} joints, {inClip.FrameCount} frames at {Fps(inClip.FrameTime)} fps"));
            table.AddRow("Reference pose", referenceFrame.HasValue ? $"frame {referenceFrame.Value}"
                : HasLafanNames(source.Skeleton) ? "the model's T-pose (LaFAN1 joint names and axes)" : "zero pose (all rotations 0)");
            if (toModel.Up != null) table.AddRow("Up axis", Markup.Escape(toModel.Up.Description + (fromModel?.Up == null ? "" : "; target: " + fromModel.Up.Description)));
            table.AddRow("Joint map", Markup.Escape($"'{toModel.Map.Name}': {toModel.Target.JointCount} model joints from {Mapped(toModel)}"));
            table.AddRow("Made up (synthesized)", Markup.Escape(toModel.SynthesizedJoints.Count == 0 ? "none"
                : string.Join(", ", toModel.SynthesizedJoints) + ": the input lacks them; each is a rigid child of its parent at the model's T-pose offset"));
            table.AddRow(fromModel == null ? "Unmapped input joints" : "Unmapped (from OTHER's reference)", Markup.Escape(toModel.UnmappedSourceJoints.Count == 0 ? "none" : MapWarnings.NameList(toModel.UnmappedSourceJoints)));
            table.AddRow("Root scale", Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "× {0:0.#####} {3}(model leg {1:0.##} ÷ input leg {2:0.###}: root height above the lowest joint in each reference pose)",
                toModel.RootScale, toModel.TargetLegLength, toModel.SourceLegLength, scaleGiven ? "as given by --scale " : "")));
            if (fromModel != null)
            {
                table.AddRow("Target", Markup.Escape($"{target}: {fromModel.Source.JointCount} joints, map '{fromModel.Map.Name}', root × {(toModel.RootScale / fromModel.RootScale).ToString("0.#####", CultureInfo.InvariantCulture)}"));
            }
            else
            {
                table.AddRow("Target", Markup.Escape($"model '{target}' skeleton ({toModel.Target.JointCount} joints)"));
            }

            table.AddRow("Frames", Markup.Escape($"{inClip.FrameCount} at {Fps(inClip.FrameTime)} fps{(fromFrame > 0 ? $" (from frame {fromFrame})" : "")}{(inputFps.HasValue ? $" (read as {Fps(1 / inputFps.Value)} fps)" : "")} → {outClip.FrameCount} at {Fps(outClip.FrameTime)} fps"));
            table.AddRow("Wrote", Markup.Escape($"{output} ({seconds.ToString("0.00", CultureInfo.InvariantCulture)} s)"));
            AnsiConsole.Write(table);
        }

        private static bool HasLafanNames(Skeleton skeleton)
        {
            foreach (string name in JointMap.Lafan1.TargetJoints) if (skeleton.IndexOf(name) < 0) return false;
            return true;
        }

        private static string Mapped(SkeletonMap map)
        {
            var parts = new List<string>();
            for (int j = 0; j < map.Target.JointCount; j++)
            {
                string t = map.Target.Names[j];
                if (map.IsSynthesized(j)) continue;
                string s = string.Join("+", map.Map.SourceChain(t)!);
                if (!string.Equals(s, t, StringComparison.Ordinal)) parts.Add(s + "→" + t);
            }

            return parts.Count == 0 ? "joints of the same names" : "joints of the same names except " + string.Join(", ", parts);
        }

        private static string Fps(double frameTime) => (1.0 / frameTime).ToString("0.##", CultureInfo.InvariantCulture);
    }
}
