using System.Globalization;
using System.IO;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Evaluation.Benchmark;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Baking
{
    /// <summary>What <c>bake</c> prints: the plan's warnings, both methods' scores beside the ground truth's skating, and one line each on keys, context, feet and timing.</summary>
    internal static class BakeSummary
    {
        public static void Print(BakeRequest request, BvhAnimation animation, BakeRun run, BakeScores scores, ModelContract contract,
            BenchmarkStatistics? statistics, double readSeconds, double loadSeconds, double totalSeconds)
        {
            MethodBake modelBake = run["Model"];
            BakePlan plan = modelBake.Plan;
            BakeSettings settings = modelBake.Method.Settings;
            foreach (string warning in plan.Warnings) AnsiConsole.MarkupLine("[yellow]warning:[/] " + Markup.Escape(warning));
            foreach (string warning in run.Warnings) AnsiConsole.MarkupLine("[yellow]warning:[/] " + Markup.Escape(TerminalText.Safe(warning, TerminalText.LineLength)));
            MotionClip motion = animation.Motion;
            int[] keys = new int[run.RigKeys.Count];
            for (int i = 0; i < keys.Length; i++) keys[i] = run.RigKeys[i];
            var table = new Table().Border(TableBorder.Rounded)
                .Title($"[bold]{Markup.Escape(Path.GetFileName(request.Input))}[/]: error on the {scores["Model"].Accuracy.Frames:N0} non-key frames (lower is better)");
            table.AddColumn("Method");
            table.AddColumn(new TableColumn("Mean joint position error (file units)").RightAligned());
            table.AddColumn(new TableColumn("L2Q").RightAligned());
            table.AddColumn(new TableColumn(statistics != null ? "L2P" : "L2P (no statistics)").RightAligned());
            table.AddColumn(new TableColumn("Foot skating (leg/s)").RightAligned());
            table.AddColumn(new TableColumn("Bake time (s)").RightAligned());
            AddRow(table, "Model (" + Path.GetFileNameWithoutExtension(contract.Source) + ")", scores["Model"], modelBake.Seconds);
            AddRow(table, "SLERP", scores["SLERP"], run["SLERP"].Seconds);
            table.AddRow("Ground truth", "-", "-", "-", BakeFeet.Format(scores.TruthSkating), "-");
            AnsiConsole.Write(table);
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "feet: {0}; foot skating: mean horizontal speed of ankles and toes on the {1:N0} (frame, joint) pairs where the ground truth's are planted (within 3 % of a leg of the ground, under 15 % of a leg per second), in leg lengths per second",
                request.Feet == null ? "not locked (--feet off)" : run.Warnings.Count > 0 ? "not locked on this rig (see the warning above)" : "locked (--feet lock: planted feet held still on the filled frames, keys untouched)", scores.TruthSkating.ContactSamples)));

            string policy = settings.ShortContext == ShortContextPolicy.RepeatEarliest ? "repeat the earliest" : "feed what exists";
            string trained = settings.TrainedPastFrames is { } p ? $"trained on {p.Min}..{p.Max} past frames" : "trained past range unknown";
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "{0:N0} frames at {1:0.##} fps, {2} keys ({3}{4}), {5} gaps; model context: up to {6} past frames ({10}), where fewer exist: {7} ({8}); {9}",
                motion.FrameCount, 1.0 / motion.FrameTime, keys.Length, KeySummary(keys), plan.FrameCount < motion.FrameCount ? $"; output frames {keys[0]}..{keys[keys.Length - 1]}" : "",
                plan.Gaps.Count, settings.PastFrames, policy, trained, run.Rig.Description,
                settings.FilledFramesAsContext ? "keys and filled frames" : "key frames only")));
            string? keyLine = BakeInput.KeyLine(run.Rig);
            if (keyLine != null) AnsiConsole.MarkupLine(Markup.Escape(keyLine));
            if (run.Rig is Core.Workflows.MappedRig { AcceptedReference: { } accepted }) AnsiConsole.MarkupLine(Markup.Escape($"warning: {request.Input}: {accepted}"));
            if (statistics != null) AnsiConsole.MarkupLine(Markup.Escape($"L2P: per-coordinate std of {statistics.Source}, frames where they are in the file (no window normalisation); L2Q: global quaternions, each in the truth's hemisphere"));
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "wrote {0} ({1}); read {2:0.000} s, model load {3:0.000} s, total {4:0.00} s",
                request.OutPath, request.Method == "model" ? "model" : "SLERP", readSeconds, loadSeconds, totalSeconds)));
        }

        private static void AddRow(Table table, string name, MethodScore score, double seconds)
        {
            BakeAccuracy a = score.Accuracy;
            table.AddRow(
                Markup.Escape(name),
                a.MeanPositionError.ToString("0.000", CultureInfo.InvariantCulture),
                a.L2Q.ToString("0.0000", CultureInfo.InvariantCulture),
                double.IsNaN(a.L2P) ? "-" : a.L2P.ToString("0.0000", CultureInfo.InvariantCulture),
                BakeFeet.Format(score.Skating),
                seconds.ToString("0.000", CultureInfo.InvariantCulture));
        }

        private static string KeySummary(int[] keys)
        {
            if (keys.Length <= 6) return string.Join(",", keys);
            return $"{keys[0]},{keys[1]},{keys[2]},…,{keys[keys.Length - 1]}";
        }
    }
}
