using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Cli;
using DeltaInterpolator.Core.IO;
using NUnit.Framework;
using static DeltaInterpolator.Tests.Cli.CliTestFiles;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// <c>pack</c>'s refusals (issue 16): links out of the package, files that are not regular, manifests whose paths
    /// climb out, names an archive cannot hold safely, paths too long for ustar, and SIGTERM mid-write leaving no
    /// temporary file. Each case broke before its fix.
    /// </summary>
    [NonParallelizable]
    public class PackVerbRefusalTests
    {
        // 5. pack followed symbolic links out of the package (/etc/passwd packed; /dev/zero read forever)
        // and 15. blocked forever on a named pipe .meta or package.json.
        [Test]
        public void PackRefusesLinksOutOfThePackageAndFilesThatAreNotRegular()
        {
            if (OperatingSystem.IsWindows()) Assert.Ignore("symbolic links and named pipes: Unix");
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            string secret = temp.Write("secret.txt", "root:x:0:0\n");
            File.CreateSymbolicLink(Path.Combine(root, "Runtime", "Leak.txt"), secret);
            temp.Write("pkg/Runtime/Leak.txt.meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000aa\n");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root, "--out", temp["out"]), "outside the package");
            Assert.That(Directory.Exists(temp["out"]) && Directory.GetFiles(temp["out"]).Length > 0, Is.False, "nothing written");

            File.Delete(Path.Combine(root, "Runtime", "Leak.txt"));
            File.CreateSymbolicLink(Path.Combine(root, "Runtime", "Leak.txt"), "/dev/zero");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root, "--out", temp["out"]), "Leak.txt");

            File.Delete(Path.Combine(root, "Runtime", "Leak.txt"));
            File.Delete(Path.Combine(root, "Runtime", "Leak.txt.meta"));
            File.Delete(Path.Combine(root, "Runtime", "Motion.cs.meta"));
            CliHarness.MakeFifo(Path.Combine(root, "Runtime", "Motion.cs.meta"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root, "--out", temp["out"]), "named pipe");

            string root2 = SmallPackage(temp, "pkg2");
            File.Delete(Path.Combine(root2, "package.json"));
            CliHarness.MakeFifo(Path.Combine(root2, "package.json"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root2, "--out", temp["out2"]), "named pipe");

            // A link inside the package to a file of the package is packed (its content).
            string root3 = SmallPackage(temp, "pkg3");
            File.CreateSymbolicLink(Path.Combine(root3, "Runtime", "Alias.cs"), Path.Combine(root3, "Runtime", "Motion.cs"));
            temp.Write("pkg3/Runtime/Alias.cs.meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ab\n");
            CliHarness.AssertSuccess(CliHarness.RunWithin(60, "pack", "--root", root3, "--out", temp["out3"]));
        }

        // 6. Archive paths that escape: a name with '\..\', a package name of '../../x', control characters.
        [TestCase("name", "../../escape")]
        [TestCase("name", "com.example/../../x")]
        [TestCase("version", "1.0.0/../../../x")]
        public void PackRefusesAManifestThatWouldMakePathsClimbOut(string field, string value)
        {
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg", field == "name" ? value : "com.example.pack", field == "version" ? value : "1.2.3");
            CliRun run = CliHarness.Run("pack", "--root", root, "--out", temp["out/deep"]);
            CliHarness.AssertOneErrorLine(run, "\"" + field + "\"");
            Assert.That(Directory.GetFiles(temp.Path, "*.tgz", SearchOption.AllDirectories), Is.Empty);
            Assert.That(Directory.GetFiles(temp.Path, "*.unitypackage", SearchOption.AllDirectories), Is.Empty);
        }

        [TestCase("Evil\\..\\..\\x.cs", "'\\'")]
        [TestCase("Bell\u0007\u001b]0;t.cs", "control", TestName = "PackRefusesFileNamesAnArchiveCannotHoldSafely(Bell BEL ESC]0;t.cs)")]
        public void PackRefusesFileNamesAnArchiveCannotHoldSafely(string name, string phrase)
        {
            if (OperatingSystem.IsWindows()) Assert.Ignore("such names cannot exist on Windows");
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            temp.Write("pkg/Runtime/" + name, "x");
            temp.Write("pkg/Runtime/" + name + ".meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ac\n");
            CliHarness.AssertOneErrorLine(CliHarness.Run("pack", "--root", root, "--out", temp["out"]), phrase);
            Assert.That(Directory.Exists(temp["out"]) && Directory.GetFiles(temp["out"]).Length > 0, Is.False);
        }

        // 11. A path too long for ustar was "this is a bug" (exit 1).
        [Test]
        public void PackRefusesAPathTooLongForUstarUpFront()
        {
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            string longName = new string('n', 120) + ".cs";
            temp.Write("pkg/Runtime/" + longName, "x");
            temp.Write("pkg/Runtime/" + longName + ".meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ad\n");
            CliHarness.AssertOneErrorLine(CliHarness.Run("pack", "--root", root, "--out", temp["out"]), "too long for a ustar");
        }

        private static string SmallPackage(TempFolder temp, string name, string packageName = "com.example.pack", string version = "1.2.3")
        {
            temp.Write(name + "/package.json", "{ \"name\": \"" + packageName.Replace("\\", "\\\\") + "\", \"version\": \"" + version + "\" }\n");
            temp.Write(name + "/package.json.meta", "fileFormatVersion: 2\nguid: 0000000000000000000000000000000a\n");
            temp.Write(name + "/Runtime.meta", "fileFormatVersion: 2\nguid: 0000000000000000000000000000000b\n");
            temp.Write(name + "/Runtime/Motion.cs", "class Motion {}\n");
            temp.Write(name + "/Runtime/Motion.cs.meta", "fileFormatVersion: 2\nguid: 0000000000000000000000000000000c\n");
            return temp[name];
        }

        // 18. SIGTERM during a write left .NAME.XXXXXXXX.tmp files behind (25 MB seen from pack): the real
        // tool in its own process, terminated while it writes its first archive.
        [Test]
        public void SigtermDuringPackRemovesTheTemporaryFile()
        {
            if (OperatingSystem.IsWindows()) Assert.Ignore("POSIX signals");
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            var random = new Random(16);
            var bytes = new byte[24 << 20];
            random.NextBytes(bytes);
            File.WriteAllBytes(Path.Combine(root, "Runtime", "Big.bin"), bytes);
            temp.Write("pkg/Runtime/Big.bin.meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ae\n");
            string outDir = temp["out"];
            var start = new ProcessStartInfo("dotnet") { UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true };
            foreach (string a in new[] { typeof(Program).Assembly.Location, "pack", "--root", root, "--out", outDir }) start.ArgumentList.Add(a);
            using Process tool = Process.Start(start)!;
            tool.StandardOutput.ReadToEndAsync();
            tool.StandardError.ReadToEndAsync();
            var clock = Stopwatch.StartNew();
            while (!tool.HasExited && clock.Elapsed.TotalSeconds < 60 && (!Directory.Exists(outDir) || TemporaryFiles(outDir).Length == 0)) System.Threading.Thread.Sleep(5);
            if (tool.HasExited) Assert.Inconclusive("pack finished before it could be interrupted");
            Assert.That(TemporaryFiles(outDir), Is.Not.Empty, "the write is under way");
            using (Process kill = Process.Start("kill", new[] { "-TERM", tool.Id.ToString(CultureInfo.InvariantCulture) })!) kill.WaitForExit();
            Assert.That(tool.WaitForExit(60_000), Is.True);
            Assert.That(tool.ExitCode, Is.EqualTo(143), "ended by SIGTERM");
            Assert.That(TemporaryFiles(outDir), Is.Empty, "no temporary file left");
        }
    }
}
