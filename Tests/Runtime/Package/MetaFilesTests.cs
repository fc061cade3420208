using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Package
{
    /// <summary>
    /// Unity imports every file and folder of a package whose path has no hidden component (a name
    /// starting with '.' or ending with '~') and ignores, with a warning, one without a .meta. This test
    /// checks what git would commit (tracked + untracked-not-ignored files): every importable file and
    /// folder has a .meta, no .meta is orphaned, no two share a GUID. Fix with `python3 Tools~/metas.py`.
    /// </summary>
    public class MetaFilesTests
    {
        private static readonly Regex GuidLine = new Regex(@"^guid:\s*([0-9a-f]{32})\s*$", RegexOptions.Multiline);

        [Test]
        public void EveryImportedFileAndFolderHasAUniqueMeta()
        {
            if (TestEnvironment.InsideUnity) Assert.Ignore("runs under dotnet test only (Unity regenerates metas itself)");
            string? root = TestEnvironment.RepositoryRoot;
            if (root == null || !Directory.Exists(Path.Combine(root, ".git")) && !File.Exists(Path.Combine(root, ".git")))
            {
                Assert.Ignore("not in a git checkout; skipping the .meta check");
            }

            List<string>? files = GitFiles(root!);
            if (files == null) Assert.Ignore("git is not available; skipping the .meta check");

            var present = new HashSet<string>(files!.Where(f => File.Exists(Path.Combine(root!, f))), StringComparer.Ordinal);
            var assets = new HashSet<string>(present.Where(f => Visible(f) && !f.EndsWith(".meta", StringComparison.Ordinal)), StringComparer.Ordinal);
            var folders = new HashSet<string>(StringComparer.Ordinal);
            foreach (string f in assets)
            {
                for (string? d = ParentOf(f); d != null; d = ParentOf(d)) folders.Add(d);
            }

            var metas = new HashSet<string>(present.Where(f => Visible(f) && f.EndsWith(".meta", StringComparison.Ordinal)), StringComparer.Ordinal);
            var missing = assets.Concat(folders).Where(a => !metas.Contains(a + ".meta")).OrderBy(a => a, StringComparer.Ordinal).ToList();
            var orphaned = metas.Where(m =>
            {
                string asset = m.Substring(0, m.Length - 5);
                return !assets.Contains(asset) && !folders.Contains(asset);
            }).OrderBy(m => m, StringComparer.Ordinal).ToList();

            var byGuid = new Dictionary<string, List<string>>();
            var unreadable = new List<string>();
            foreach (string m in metas)
            {
                Match match = GuidLine.Match(File.ReadAllText(Path.Combine(root!, m)));
                if (!match.Success) { unreadable.Add(m); continue; }
                if (!byGuid.TryGetValue(match.Groups[1].Value, out List<string>? list)) byGuid[match.Groups[1].Value] = list = new List<string>();
                list.Add(m);
            }

            var duplicates = byGuid.Where(p => p.Value.Count > 1).Select(p => p.Key + ": " + string.Join(", ", p.Value)).ToList();
            string report = $"missing .meta: {string.Join(", ", missing)}\norphaned .meta: {string.Join(", ", orphaned)}\nno guid: {string.Join(", ", unreadable)}\nduplicate GUIDs: {string.Join("; ", duplicates)}\nRun `python3 Tools~/metas.py` to create missing metas.";
            Assert.That(missing, Is.Empty, report);
            Assert.That(orphaned, Is.Empty, report);
            Assert.That(unreadable, Is.Empty, report);
            Assert.That(duplicates, Is.Empty, report);
        }

        [TestCase("Runtime/Core/Bvh/BvhReader.cs", true)]
        [TestCase("Tools~/Cli/Program.cs", false)]
        [TestCase("Samples~/Demo/README.md", false)]
        [TestCase(".ci/run", false)]
        [TestCase("Training/.pytest_cache/x", false)]
        [TestCase("README.md", true)]
        public void HiddenPathsFollowUnitysRule(string path, bool visible)
        {
            Assert.That(Visible(path), Is.EqualTo(visible));
        }

        private static bool Visible(string path) => path.Split('/').All(c => !c.StartsWith(".", StringComparison.Ordinal) && !c.EndsWith("~", StringComparison.Ordinal));

        private static string? ParentOf(string path)
        {
            int slash = path.LastIndexOf('/');
            return slash <= 0 ? null : path.Substring(0, slash);
        }

        private static List<string>? GitFiles(string root)
        {
            try
            {
                var info = new ProcessStartInfo("git", "ls-files -z --cached --others --exclude-standard")
                {
                    WorkingDirectory = root,
                    RedirectStandardOutput = true,
                    RedirectStandardError = true,
                    UseShellExecute = false,
                };
                using Process? process = Process.Start(info);
                if (process == null) return null;
                string output = process.StandardOutput.ReadToEnd();
                process.WaitForExit();
                if (process.ExitCode != 0) return null;
                return output.Split(new[] { '\0' }, StringSplitOptions.RemoveEmptyEntries).Distinct().ToList();
            }
            catch (System.ComponentModel.Win32Exception)
            {
                return null;
            }
        }
    }
}
