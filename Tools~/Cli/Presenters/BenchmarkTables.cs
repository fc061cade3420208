using System;
using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Evaluation.Metrics;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Presenters
{
    /// <summary>The benchmark's results as the official tables: one per metric, a row per method, a column per length.</summary>
    internal static class BenchmarkTables
    {
        public static void Print(BenchmarkReport report)
        {
            PrintTable(report, "L2Q", "global quaternion error", t => t.L2Q, "0.0000");
            PrintTable(report, "L2P", "global position error", t => t.L2P, "0.0000");
            PrintTable(report, "NPSS", "power spectrum distance", t => t.Npss, "0.00000");
            AnsiConsole.MarkupLine("Lower is better. Lengths are missing frames; Interp. = SLERP + root LERP, Zero-V = last past pose held.");
            PrintSkating(report);
        }

        // Not an official metric: an extra table after them, with the ground truth's own skating as the floor.
        private static void PrintSkating(BenchmarkReport report)
        {
            var table = new Table().Border(TableBorder.Rounded)
                .Title("[bold]Foot skating[/] (leg lengths per second where the ground truth's feet are planted; not an official metric)");
            table.AddColumn(new TableColumn("Lengths"));
            foreach (int n in report.Lengths) table.AddColumn(new TableColumn(n.ToString(CultureInfo.InvariantCulture)).RightAligned());
            for (int m = 0; m < report.MethodIds.Count; m++)
            {
                var cells = new List<string> { Markup.Escape(report.MethodNames[m]) };
                foreach (int n in report.Lengths) cells.Add(report.Get(report.MethodIds[m], n).FootSkating.ToString("0.000", CultureInfo.InvariantCulture));
                table.AddRow(cells.ToArray());
            }

            var truth = new List<string> { "Ground truth" };
            foreach (int n in report.Lengths) truth.Add(report.GroundTruth(n).FootSkating.ToString("0.000", CultureInfo.InvariantCulture));
            table.AddRow(truth.ToArray());
            AnsiConsole.Write(table);
            AnsiConsole.MarkupLine("Foot skating: mean horizontal speed of the result's ankles and toes on filled frames where the ground truth's are within 3 % of a leg length of the file's ground and slower than 15 % of a leg length per second.");
        }

        private static void PrintTable(BenchmarkReport report, string metric, string meaning, Func<MetricTotals, double> value, string format)
        {
            var table = new Table().Border(TableBorder.Rounded)
                .Title($"[bold]{metric}[/] ({Markup.Escape(meaning)})");
            table.AddColumn(new TableColumn("Lengths"));
            foreach (int n in report.Lengths) table.AddColumn(new TableColumn(n.ToString(CultureInfo.InvariantCulture)).RightAligned());
            for (int m = 0; m < report.MethodIds.Count; m++)
            {
                var cells = new List<string> { Markup.Escape(report.MethodNames[m]) };
                foreach (int n in report.Lengths)
                {
                    cells.Add(value(report.Get(report.MethodIds[m], n)).ToString(format, CultureInfo.InvariantCulture));
                }

                table.AddRow(cells.ToArray());
            }

            AnsiConsole.Write(table);
        }
    }
}
