using System;
using System.Diagnostics;
using System.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.IO
{
    /// <summary>Temporary folders and special files (named pipes, links) made with the system's own tools.</summary>
    public sealed class FileSystemFixtures : IDisposable
    {
        public FileSystemFixtures()
        {
            Folder = Path.Combine(Path.GetTempPath(), "deltainterp-io-" + Guid.NewGuid().ToString("N").Substring(0, 10));
            Directory.CreateDirectory(Folder);
        }

        /// <summary>The temporary folder (deleted by <see cref="Dispose"/>).</summary>
        public string Folder { get; }

        /// <summary>A path inside <see cref="Folder"/>.</summary>
        public string this[string name] => Path.Combine(Folder, name);

        /// <summary>Writes <paramref name="text"/> to <paramref name="name"/>; returns the path.</summary>
        public string Write(string name, string text)
        {
            string path = this[name];
            File.WriteAllText(path, text);
            return path;
        }

        /// <summary>Runs a Unix tool (mkfifo, ln); skips the test on Windows or when the tool fails.</summary>
        public static void Unix(string tool, params string[] args)
        {
            if (Environment.OSVersion.Platform != PlatformID.Unix && Environment.OSVersion.Platform != PlatformID.MacOSX)
            {
                Assert.Ignore($"{tool} is a Unix tool; skipping on this platform");
            }

            var start = new ProcessStartInfo(tool, string.Join(" ", Array.ConvertAll(args, a => "\"" + a.Replace("\\", "\\\\").Replace("\"", "\\\"") + "\"")))
            {
                UseShellExecute = false,
            };
            try
            {
                using (Process? process = Process.Start(start))
                {
                    process!.WaitForExit();
                    if (process.ExitCode != 0) Assert.Ignore($"{tool} failed (exit {process.ExitCode}); skipping");
                }
            }
            catch (System.ComponentModel.Win32Exception e)
            {
                Assert.Ignore($"{tool} is not available ({e.Message}); skipping");
            }
        }

        /// <summary>Files in the folder, to show no temporary file was left behind.</summary>
        public string[] Files => Directory.GetFiles(Folder);

        public void Dispose()
        {
            try
            {
                Directory.Delete(Folder, true);
            }
            catch (IOException)
            {
            }
        }
    }
}
