using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text.Json.Nodes;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.IO;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Speed
{
    /// <summary>
    /// The same request timed in PyTorch eager by the trainer (<c>python3 -m deltainterp.speed</c>; same
    /// architecture with random weights, then the paper's preset) on the same thread count: the reference the
    /// C# runtime's speed-up is measured against. Needs a checkout (the trainer's sources) and Python with torch.
    /// </summary>
    internal static class PyTorchSpeed
    {
        /// <summary>Runs the trainer's timing and returns its JSON ({"torch", "parameters", "transition_ms", ...}).</summary>
        /// <param name="root">The checkout (<see cref="RepositoryCheckout.Find"/>), or null.</param>
        /// <param name="contract">The model whose architecture PyTorch rebuilds.</param>
        /// <param name="threads">Intra-op threads given to torch.</param>
        /// <param name="repeats">Timed repetitions (at most 200: eager PyTorch is slow).</param>
        public static JsonObject Run(string? root, ModelContract contract, int threads, int repeats)
        {
            if (root == null || !File.Exists(Path.Combine(root, "Training", "Python~", "deltainterp", "speed.py")))
            {
                throw new CliErrors.UsageException("inbetween speed: --pytorch needs the repository's Training/Python~/deltainterp (speed.py); expected to run from a checkout of the package");
            }

            string python = Environment.GetEnvironmentVariable("DELTAINTERP_PYTHON") ?? "/usr/bin/python3";
            string config = Path.Combine(Path.GetTempPath(), $"deltainterp-speed-{Environment.ProcessId}.json");
            string output = Path.Combine(Path.GetTempPath(), $"deltainterp-speed-{Environment.ProcessId}.out.json");
            OutputFile.WriteAllText(config, contract.DescriptionJson);
            try
            {
                AnsiConsole.MarkupLine(Markup.Escape($"Timing the same request in PyTorch eager ({python} -m deltainterp.speed, {threads} thread(s), then the paper preset)..."));
                var start = new ProcessStartInfo(python)
                {
                    WorkingDirectory = root,
                    UseShellExecute = false,
                    RedirectStandardError = true,
                };
                foreach (string a in new[] { "-m", "deltainterp.speed", "--config", config, "--threads", threads.ToString(CultureInfo.InvariantCulture), "--repeats", Math.Min(repeats, 200).ToString(CultureInfo.InvariantCulture), "--json", output })
                {
                    start.ArgumentList.Add(a);
                }

                start.Environment["PYTHONPATH"] = Path.Combine(root, "Training", "Python~");
                using Process? process = Process.Start(start);
                if (process == null) throw new CliErrors.UsageException($"inbetween speed: could not start {python}; expected Python 3 with torch (set DELTAINTERP_PYTHON)");
                string stderr = process.StandardError.ReadToEnd();
                process.WaitForExit();
                if (process.ExitCode != 0 || !File.Exists(output))
                {
                    string last = stderr.Trim().Split('\n')[^1];
                    throw new CliErrors.UsageException($"inbetween speed: {python} -m deltainterp.speed failed ({last}); expected Python 3 with torch and numpy (see Training/README)");
                }

                return JsonNode.Parse(File.ReadAllText(output))!.AsObject();
            }
            finally
            {
                File.Delete(config);
                File.Delete(output);
            }
        }
    }
}
