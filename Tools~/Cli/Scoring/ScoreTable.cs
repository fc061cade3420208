using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Evaluation.Baking;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Scoring
{
    /// <summary><c>score</c>'s table: every file, every subject (when there are several) and all files, each method's values and its ratio to SLERP.</summary>
    internal static class ScoreTable
    {
        private static string Unit(Core.Baking.KeySpacing every) => every.Unit switch
        {
            Core.Baking.KeySpacingUnit.InputFrames => every.Value.ToString("0", CultureInfo.InvariantCulture) + " input frames",
            Core.Baking.KeySpacingUnit.ModelFrames => every.Value.ToString("0", CultureInfo.InvariantCulture) + " model frames",
            _ => every.Value.ToString("0.###", CultureInfo.InvariantCulture) + " s",
        };

        public static void Print(ScoreSheet sheet, Core.Baking.KeySpacing every)
        {
            int methods = sheet.Methods.Count;
            var table = new Table().Border(TableBorder.Rounded)
                .Title($"[bold]Keys every {Unit(every)}[/]: mean joint position error ÷ leg length, and L2Q, over non-key frames (× SLERP in brackets; lower is better)");
            table.AddColumn("File");
            table.AddColumn(new TableColumn("Frames").RightAligned());
            // Whole method names in a legend above the table, numbers in the headers: a column narrower than a model's
            // name would cut it ("DeltaInterpola…"), and two exports differ only at the end of their names.
            var legend = new List<string>();
            for (int i = 0; i < methods; i++)
            {
                legend.Add(string.Format(CultureInfo.InvariantCulture, "[{0}] {1}", i + 1, sheet.Methods[i]));
                table.AddColumn(new TableColumn(string.Format(CultureInfo.InvariantCulture, "[[{0}]] pos / L2Q", i + 1)).RightAligned());
            }

            foreach (string line in legend) AnsiConsole.WriteLine(line);
            void AddRow(string label, MethodErrors e, int frames, bool bold)
            {
                var cells = new List<string> { bold ? $"[bold]{Markup.Escape(label)}[/]" : Markup.Escape(label), frames.ToString("N0", CultureInfo.InvariantCulture) };
                for (int i = 0; i < methods; i++)
                {
                    string cell = string.Format(CultureInfo.InvariantCulture, "{0:0.0000} / {1:0.000}", e.PositionPerLeg[i], e.L2Q[i]);
                    if (i < methods - 1) cell += string.Format(CultureInfo.InvariantCulture, " ({0:0.00} / {1:0.00})", e.PositionRatio(i), e.L2QRatio(i));
                    cells.Add(cell);
                }

                table.AddRow(cells.ToArray());
            }

            foreach (ScoreRow r in sheet.Rows) AddRow(r.File, r.Errors, r.Frames, false);
            SortedDictionary<string, List<ScoreRow>> groups = sheet.Groups();
            groups.Remove(""); // files without a subject are in the total only
            if (groups.Count > 1)
            {
                foreach (var g in groups)
                {
                    ScoreTotal t = sheet.Total(g.Value);
                    AddRow("subject " + g.Key, t.Errors, t.Frames, true);
                }
            }

            ScoreTotal all = sheet.Total();
            AddRow($"all {sheet.Rows.Count} files", all.Errors, all.Frames, true);
            AnsiConsole.Write(table);
            if (all.Errors.ContactSamples == 0) return;
            var parts = new List<string>();
            for (int i = 0; i < methods; i++) parts.Add(string.Format(CultureInfo.InvariantCulture, "{0} {1:0.000}", sheet.Methods[i], all.Errors.FootSkating[i]));
            AnsiConsole.MarkupLine(Markup.Escape(string.Format(CultureInfo.InvariantCulture,
                "foot skating over all files (leg lengths per second, on the {0:N0} (frame, joint) pairs where the ground truth's feet are planted): {1}; ground truth {2:0.000}",
                all.Errors.ContactSamples, string.Join(", ", parts), all.Errors.TruthFootSkating)));
        }
    }
}
