using System.Collections.Generic;
using System.Globalization;
using System.Text.Json.Nodes;
using DeltaInterpolator.Evaluation.Speed;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Presenters
{
    /// <summary>
    /// The one-screen summary of <c>inbetween speed</c>: a table of median / p95 per length, then the lazy,
    /// SLERP + FK and allocation lines. Reads the written JSON document (<see cref="SpeedJson"/>), so what
    /// the screen shows is what the file holds, rounding included.
    /// </summary>
    internal static class SpeedTable
    {
        public static void Print(JsonObject r, bool withPyTorch)
        {
            var table = new Table().Border(TableBorder.Rounded).Title($"[bold]speed[/] ({r["threads"]} thread(s); median / p95)");
            table.AddColumn("Measurement");
            foreach (int n in RuntimeSpeed.Lengths) table.AddColumn(new TableColumn("n = " + n).RightAligned());
            AddRow(table, "C# transition (ms)", r["transition_ms"]);
            AddRow(table, "C# network only (ms)", r["network_ms"]);
            if (withPyTorch)
            {
                AddRow(table, "PyTorch transition (ms)", r["pytorch_transition_ms"]);
                AddRow(table, "PyTorch, paper preset (ms)", r["paper_pytorch_transition_ms"]);
                var cells = new List<string> { "speed-up vs PyTorch (×)" };
                foreach (int n in RuntimeSpeed.Lengths) cells.Add(r["speedup_vs_pytorch"]![SpeedJson.Key(n)]!.GetValue<double>().ToString("0.0", CultureInfo.InvariantCulture));
                table.AddRow(cells.ToArray());
            }

            AnsiConsole.Write(table);
            if (r["lazy_frame_ms"] is JsonObject lazy)
            {
                AnsiConsole.MarkupLine(Markup.Escape($"lazy: keys {Cell(r["lazy_keys_ms"])} ms, one frame {Cell(lazy)} ms = {r["lazy_frame_fraction_of_transition_30"]!.GetValue<double>():0.000} of a whole 30-frame transition"));
            }

            AnsiConsole.MarkupLine(Markup.Escape($"SLERP + FK alone (n = 30): {Cell(r["slerp_fk_us"])} µs; managed allocation per transition in steady state: {r["alloc_bytes_per_transition"]} bytes"));
        }

        private static void AddRow(Table table, string name, JsonNode? values)
        {
            var cells = new List<string> { name };
            foreach (int n in RuntimeSpeed.Lengths) cells.Add(Cell(values?[SpeedJson.Key(n)]));
            table.AddRow(cells.ToArray());
        }

        /// <summary>"median / p95" with as many decimals as the size of the numbers warrants.</summary>
        private static string Cell(JsonNode? timing)
        {
            if (timing == null) return "-";
            double median = timing["median"]!.GetValue<double>(), p95 = timing["p95"]!.GetValue<double>();
            string format = median < 1 ? "0.000" : median < 100 ? "0.00" : "0.0";
            return median.ToString(format, CultureInfo.InvariantCulture) + " / " + p95.ToString(format, CultureInfo.InvariantCulture);
        }
    }
}
