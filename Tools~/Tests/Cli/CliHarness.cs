using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Threading.Tasks;
using DeltaInterpolator.Cli;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>What one run of the tool showed: exit status, standard output and standard error.</summary>
    public sealed class CliRun
    {
        public CliRun(string[] args, int exitCode, string stdout, string stderr)
        {
            Args = args;
            ExitCode = exitCode;
            Stdout = stdout;
            Stderr = stderr;
        }

        public string[] Args { get; }

        public int ExitCode { get; }

        public string Stdout { get; }

        public string Stderr { get; }

        /// <summary>The lines of standard error (without a trailing empty one).</summary>
        public string[] ErrorLines
        {
            get
            {
                string[] lines = Stderr.Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
                return lines.Length > 0 && lines[lines.Length - 1].Length == 0 ? lines.Take(lines.Length - 1).ToArray() : lines;
            }
        }

        public override string ToString() => $"inbetween {string.Join(" ", Args)} → exit {ExitCode}\nstderr: {Stderr}\nstdout (start): {(Stdout.Length > 400 ? Stdout.Substring(0, 400) : Stdout)}";
    }

    /// <summary>Runs <c>inbetween</c> in this process through <see cref="Program.Run"/> and checks the CLI contract.</summary>
    public static class CliHarness
    {
        /// <summary>Runs the tool with <paramref name="args"/>.</summary>
        public static CliRun Run(params string[] args)
        {
            var stdout = new StringWriter(CultureInfo.InvariantCulture);
            var stderr = new StringWriter(CultureInfo.InvariantCulture);
            int code = Program.Run(args, stdout, stderr);
            return new CliRun(args, code, stdout.ToString(), stderr.ToString());
        }

        /// <summary>
        /// Runs the tool, failing the test instead of hanging when it does not finish within
        /// <paramref name="seconds"/> (a named pipe opened for reading blocks forever).
        /// </summary>
        public static CliRun RunWithin(double seconds, params string[] args)
        {
            Task<CliRun> run = Task.Run(() => Run(args));
            if (!run.Wait(TimeSpan.FromSeconds(seconds)))
            {
                Assert.Fail($"inbetween {string.Join(" ", args)} did not finish within {seconds} s (blocked?)");
            }

            return run.Result;
        }

        /// <summary>
        /// The contract for bad input: exit 2 and exactly one line on stderr that reads
        /// <c>…: what; expected …</c>, with no raw control characters and a bounded length.
        /// </summary>
        public static string AssertOneErrorLine(CliRun run, string? phrase = null)
        {
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            string[] lines = run.ErrorLines;
            Assert.That(lines, Has.Length.EqualTo(1), run.ToString());
            string line = lines[0];
            Assert.That(line, Does.Contain(": "), run.ToString());
            Assert.That(line, Does.Contain("; expected"), run.ToString());
            Assert.That(line.Any(TerminalText.IsUnsafe), Is.False, "raw control characters on stderr: " + run);
            Assert.That(line.Length, Is.LessThanOrEqualTo(TerminalText.LineLength + 64), "overlong error line");
            Assert.That(line, Does.Not.Contain("this is a bug"), run.ToString());
            if (phrase != null) Assert.That(line, Does.Contain(phrase), run.ToString());
            return line;
        }

        /// <summary>Success: exit 0, nothing on stderr, no raw control characters on stdout.</summary>
        public static void AssertSuccess(CliRun run)
        {
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            Assert.That(run.Stderr, Is.Empty, run.ToString());
            Assert.That(run.Stdout.Any(c => c != '\n' && c != '\r' && TerminalText.IsUnsafe(c)), Is.False, "raw control characters on stdout: " + run);
        }

        /// <summary>
        /// A small walking clip on a two-joint skeleton (hips with 6 channels, spine with 3); with
        /// <paramref name="hugeAtFrame"/> ≥ 0 that frame's root holds ±1e308 (finite, but FK overflows).
        /// </summary>
        public static string WalkClip(int frames, int hugeAtFrame = -1)
        {
            var sb = new StringBuilder();
            sb.Append("HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n");
            sb.Append("\tJOINT Spine\n\t{\n\t\tOFFSET 0 10 0\n\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 5 0\n\t\t}\n\t}\n}\n");
            sb.Append("MOTION\nFrames: ").Append(frames).Append("\nFrame Time: 0.033333\n");
            for (int f = 0; f < frames; f++)
            {
                double t = f / 30.0;
                double[] v = { 20 * t, 90 + Math.Sin(t), 0, 5 * Math.Sin(t), 20 * t, 3 * Math.Cos(t), 10 * Math.Sin(2 * t), 4, 1 };
                if (f == hugeAtFrame)
                {
                    v[0] = 1e308;
                    v[2] = -1e308;
                }

                sb.Append(string.Join(" ", v.Select(x => x.ToString(Math.Abs(x) < 1e100 ? "0.000000" : "R", CultureInfo.InvariantCulture)))).Append('\n');
            }

            return sb.ToString();
        }

        /// <summary>A chain of <paramref name="depth"/> joints, each inside the previous, one frame.</summary>
        public static string DeepChain(int depth)
        {
            var sb = new StringBuilder(depth * 80);
            sb.Append("HIERARCHY\nROOT J0\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n");
            for (int i = 1; i < depth; i++) sb.Append("JOINT J").Append(i).Append("\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Yrotation Xrotation\n");
            sb.Append("End Site\n{\nOFFSET 0 1 0\n}\n");
            for (int i = 0; i < depth; i++) sb.Append("}\n");
            sb.Append("MOTION\nFrames: 1\nFrame Time: 0.033333\n");
            sb.Append(string.Join(" ", Enumerable.Repeat("0", 3 + 3 * depth))).Append('\n');
            return sb.ToString();
        }

        /// <summary>Creates a named pipe with mkfifo, or skips the test where that is impossible.</summary>
        public static string MakeFifo(string path)
        {
            if (System.Runtime.InteropServices.RuntimeInformation.IsOSPlatform(System.Runtime.InteropServices.OSPlatform.Windows))
            {
                Assert.Ignore("named pipes in the file system are a Unix feature; skipping on Windows");
            }

            var start = new System.Diagnostics.ProcessStartInfo("mkfifo") { UseShellExecute = false };
            start.ArgumentList.Add(path);
            using var process = System.Diagnostics.Process.Start(start);
            process!.WaitForExit();
            if (process.ExitCode != 0) Assert.Ignore("mkfifo failed; skipping the named-pipe case");
            return path;
        }
    }

    /// <summary>A fresh temporary folder, deleted afterwards.</summary>
    public sealed class TempFolder : IDisposable
    {
        public TempFolder()
        {
            Path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "inbetween-cli-" + Guid.NewGuid().ToString("N").Substring(0, 10));
            Directory.CreateDirectory(Path);
        }

        public string Path { get; }

        public string this[string name] => System.IO.Path.Combine(Path, name);

        /// <summary>Writes <paramref name="text"/> to <paramref name="name"/> (creating folders) and returns the path.</summary>
        public string Write(string name, string text)
        {
            string path = this[name];
            Directory.CreateDirectory(System.IO.Path.GetDirectoryName(path)!);
            File.WriteAllText(path, text);
            return path;
        }

        public void Dispose()
        {
            try
            {
                Directory.Delete(Path, true);
            }
            catch (IOException)
            {
            }
        }
    }
}
