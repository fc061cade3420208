using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Formats.Tar;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Text;
using DeltaInterpolator.Cli;
using DeltaInterpolator.Cli.Packaging;
using DeltaInterpolator.Core.Inference;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// The release archives of <c>inbetween pack</c>, built from a small package tree and read back with
    /// a tar reader: the UPM tarball holds package/package.json and every importable file with its .meta
    /// (hidden tool folders out, Samples~ in); the .unitypackage holds one folder per asset named by the
    /// GUID of its .meta, with asset (files only), asset.meta and pathname.
    /// </summary>
    public class PackTests
    {
        private string _root = "";

        [SetUp]
        public void CreatePackage()
        {
            _root = Path.Combine(Path.GetTempPath(), "pack-test-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_root);
            Write("package.json", "{ \"name\": \"com.example.pack\", \"version\": \"1.2.3\" }\n");
            Meta("package.json", "0000000000000000000000000000000a");
            Write("Runtime/Motion.cs", "class Motion {}\n");
            Meta("Runtime", "0000000000000000000000000000000b");
            Meta("Runtime/Motion.cs", "0000000000000000000000000000000c");
            Write("Runtime/Models/tiny.onnx", "\u0008\u0001binary-ish");
            Meta("Runtime/Models", "0000000000000000000000000000000d");
            Meta("Runtime/Models/tiny.onnx", "0000000000000000000000000000000e");
            Write("Samples~/Transitions/README.md", "steps\n");
            Write("Tools~/Cli/Program.cs", "tool\n");
            Write("UnityPackage/HostProject~/Packages/manifest.json", "{}\n");
            Write("UnityPackage/README.md", "release\n");
            Meta("UnityPackage", "0000000000000000000000000000000f");
            Meta("UnityPackage/README.md", "00000000000000000000000000000010");
            Write(".ci/run", "#!/bin/sh\n");
        }

        [TearDown]
        public void DeletePackage()
        {
            try { Directory.Delete(_root, true); } catch (IOException) { } catch (UnauthorizedAccessException) { }
        }

        private static readonly string[] ExpectedTarball =
        {
            "package/Runtime.meta", "package/Runtime/Models.meta", "package/Runtime/Models/tiny.onnx", "package/Runtime/Models/tiny.onnx.meta",
            "package/Runtime/Motion.cs", "package/Runtime/Motion.cs.meta", "package/Samples~/Transitions/README.md",
            "package/UnityPackage.meta", "package/UnityPackage/README.md", "package/UnityPackage/README.md.meta",
            "package/package.json", "package/package.json.meta",
        };

        [Test]
        public void TheTarballHoldsEveryImportableFileWithItsMetaUnderPackage()
        {
            Dictionary<string, byte[]> entries = ReadTar(Pack(PackageArchives.WriteUpmTarball, PackageContents.Read(_root)));

            Assert.That(entries.Keys.OrderBy(k => k, StringComparer.Ordinal), Is.EqualTo(ExpectedTarball));
            Assert.That(Encoding.UTF8.GetString(entries["package/package.json"]), Does.Contain("com.example.pack"));
            Assert.That(entries["package/Runtime/Models/tiny.onnx"], Is.EqualTo(File.ReadAllBytes(Path.Combine(_root, "Runtime/Models/tiny.onnx"))));
        }

        [Test]
        public void InAGitRepositoryIgnoredFilesStayOut()
        {
            Write(".gitignore", "Training/runs/\n");
            Write("Training/runs/checkpoint.pt", "weights\n");
            if (!Git("init -q") || !Git("add -A"))
            {
                Assert.Ignore("git is not available here; the walk-the-tree mode is tested on its own");
            }

            Dictionary<string, byte[]> entries = ReadTar(Pack(PackageArchives.WriteUpmTarball, PackageContents.Read(_root)));

            Assert.That(entries.Keys.OrderBy(k => k, StringComparer.Ordinal), Is.EqualTo(ExpectedTarball));
        }

        [Test]
        public void TheUnityPackageHoldsOneGuidFolderPerAssetWithAssetMetaAndPathname()
        {
            PackageContents contents = PackageContents.Read(_root);
            Dictionary<string, byte[]> entries = ReadTar(Pack(PackageArchives.WriteUnityPackage, contents));

            var folders = entries.Keys.Select(k => k.Split('/')[0]).Distinct().OrderBy(k => k, StringComparer.Ordinal).ToList();
            var metas = Directory.GetFiles(_root, "*.meta", SearchOption.AllDirectories);
            Assert.That(folders.Count, Is.EqualTo(metas.Length), "one folder per .meta");
            foreach (string metaFile in metas)
            {
                string metaText = File.ReadAllText(metaFile);
                string guid = metaText.Split('\n').Single(l => l.StartsWith("guid: ", StringComparison.Ordinal)).Substring(6).Trim();
                string assetPath = Path.GetRelativePath(_root, metaFile).Replace('\\', '/');
                assetPath = assetPath.Substring(0, assetPath.Length - ".meta".Length);
                string full = Path.Combine(_root, assetPath);
                Assert.That(entries.ContainsKey(guid + "/asset.meta"), Is.True, assetPath);
                Assert.That(Encoding.UTF8.GetString(entries[guid + "/asset.meta"]), Is.EqualTo(metaText), assetPath);
                Assert.That(Encoding.UTF8.GetString(entries[guid + "/pathname"]), Is.EqualTo("Packages/com.example.pack/" + assetPath));
                if (File.Exists(full))
                {
                    Assert.That(entries[guid + "/asset"], Is.EqualTo(File.ReadAllBytes(full)), assetPath);
                }
                else
                {
                    Assert.That(Directory.Exists(full), Is.True);
                    Assert.That(entries.ContainsKey(guid + "/asset"), Is.False, "folders have no asset file: " + assetPath);
                }
            }

            Assert.That(entries.Keys.Any(k => k.Contains("Tools~") || k.Contains("Samples~")), Is.False);
            Assert.That(entries.Values.Select(v => Encoding.UTF8.GetString(v)).Any(v => v.Contains("HostProject~")), Is.False);
        }

        [Test]
        public void AnImportableFileWithoutAMetaIsRefused()
        {
            Write("Runtime/Orphan.cs", "class Orphan {}\n");

            var e = Assert.Throws<CliErrors.UsageException>(() => PackageContents.Read(_root));
            Assert.That(e!.Message, Does.Contain("Orphan.cs: has no .meta"));
        }

        [Test]
        public void TwoMetasWithOneGuidAreRefused()
        {
            Write("Runtime/Twin.cs", "class Twin {}\n");
            Meta("Runtime/Twin.cs", "0000000000000000000000000000000c");

            var e = Assert.Throws<CliErrors.UsageException>(() => PackageContents.Read(_root));
            Assert.That(e!.Message, Does.Contain("0000000000000000000000000000000c"));
        }

        [Test]
        public void TheSameTreeGivesTheSameBytes()
        {
            byte[] first = Pack(PackageArchives.WriteUpmTarball, PackageContents.Read(_root));
            byte[] second = Pack(PackageArchives.WriteUpmTarball, PackageContents.Read(_root));
            Assert.That(second, Is.EqualTo(first));
        }

        /// <summary>
        /// Issue 17: what Unity imports from the tarball <c>inbetween pack</c> writes of this repository. No
        /// training source (<c>.py</c>), checkpoint (<c>.pt</c>) or test-fixture model (<c>.onnx</c> outside
        /// <c>Runtime/Models</c>, which Sentis would import into every model picker) may be an asset: each such
        /// entry must lie under a component Unity hides. Every entry Unity does import has its <c>.meta</c>, and
        /// so has each folder above it. The shipped models are imported (with their metas). The
        /// <c>.unitypackage</c>, whose every asset is imported, holds none of those files either.
        /// </summary>
        [Test]
        public void ThisRepositorysTarballImportsNoPythonCheckpointOrFixtureModel()
        {
            string root = TestEnvironment.RepositoryRoot ?? "";
            if (root.Length == 0) Assert.Ignore("the repository (package.json beside Runtime/) is not above the test assembly");
            Assert.That(File.Exists(Path.Combine(root, "Tests", "Fixtures~", "tiny-model.onnx")), Is.True, "the fixture models this test keeps out of Unity");

            using var temp = new TempFolder();
            string tgz = temp["package.tgz"];
            string unityPackage = temp["package.unitypackage"];
            CliRun run = CliHarness.RunWithin(600, "pack", "--root", root, "--tgz", tgz, "--unitypackage", unityPackage);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString()); // stderr carries the progress bars of a 40 MB pack

            var entries = new HashSet<string>(StringComparer.Ordinal);
            foreach (string name in TarNames(tgz))
            {
                Assert.That(name, Does.StartWith("package/"));
                entries.Add(name.Substring("package/".Length));
            }

            var imported = entries.Where(e => !UnityHides(e)).ToList();
            Assert.That(imported.Where(NotAnAssetOfAPlayer), Is.Empty, "training files or fixture models Unity would import");
            foreach (string asset in imported.Where(e => !e.EndsWith(".meta", StringComparison.Ordinal)))
            {
                Assert.That(entries.Contains(asset + ".meta"), Is.True, asset + " is imported without its .meta");
                for (int slash = asset.LastIndexOf('/'); slash > 0; slash = asset.LastIndexOf('/', slash - 1))
                {
                    Assert.That(entries.Contains(asset.Substring(0, slash) + ".meta"), Is.True, asset.Substring(0, slash) + "/ is imported without its .meta");
                }
            }

            Assert.That(imported, Does.Contain("Runtime/Models/DeltaInterpolator-CMU.onnx").And.Contain("Runtime/Models/DeltaInterpolator-CMU.onnx.meta"), "the default model is imported");
            // Issue 27: the non-commercial LaFAN1 graphs enter no project with the package, only with their opt-in sample.
            Assert.That(imported.Where(e => e.Contains("DeltaInterpolator-LaFAN1")), Is.Empty, "the LaFAN1 model is imported with the package");
            Assert.That(entries, Does.Contain(ShippedModels.Lafan1).And.Contain(ShippedModels.Lafan1 + ".meta"), "the LaFAN1 model is carried as its sample");
            Assert.That(entries.Any(e => e.EndsWith(".py", StringComparison.Ordinal) || e.EndsWith(".pt", StringComparison.Ordinal)), Is.False,
                "Training/Python~ and Tests/Fixtures~ are not carried at all");

            var unityPaths = new List<string>();
            static bool IsPathname(string name) => name.EndsWith("/pathname", StringComparison.Ordinal);
            foreach ((string name, byte[] data) in TarFiles(unityPackage, IsPathname))
            {
                if (IsPathname(name)) unityPaths.Add(Encoding.UTF8.GetString(data));
            }

            const string unityRoot = "Packages/com.deltainterpolator.inbetweening/";
            Assert.That(unityPaths, Does.Contain(unityRoot + "Runtime/Models/DeltaInterpolator-CMU.onnx"));
            Assert.That(unityPaths.Where(p => !p.StartsWith(unityRoot, StringComparison.Ordinal)), Is.Empty, "every .unitypackage asset lies in the package");
            Assert.That(unityPaths.Select(p => p.Substring(unityRoot.Length)).Where(p => UnityHides(p) || NotAnAssetOfAPlayer(p)), Is.Empty,
                ".unitypackage assets that are hidden, training files or fixture models");
        }

        /// <summary>
        /// Unity's hidden-asset rule (manual, "Special folder names → Hidden assets"): a file or folder whose
        /// name starts with '.', ends with '~', is <c>cvs</c>, or a file with the extension <c>.tmp</c>, and
        /// everything inside such a folder, is not imported.
        /// </summary>
        private static bool UnityHides(string path)
        {
            string[] parts = path.Split('/');
            for (int i = 0; i < parts.Length; i++)
            {
                string c = parts[i];
                if (c.StartsWith(".", StringComparison.Ordinal) || c.EndsWith("~", StringComparison.Ordinal) || string.Equals(c, "cvs", StringComparison.OrdinalIgnoreCase)) return true;
                if (i == parts.Length - 1 && c.EndsWith(".tmp", StringComparison.OrdinalIgnoreCase)) return true;
            }

            return false;
        }

        /// <summary>Python sources and caches, PyTorch checkpoints, and any ONNX model other than the shipped ones.</summary>
        private static bool NotAnAssetOfAPlayer(string path)
        {
            string p = path.EndsWith(".meta", StringComparison.Ordinal) ? path.Substring(0, path.Length - ".meta".Length) : path;
            string[] training = { ".py", ".pyc", ".pt", ".pth", ".ckpt" };
            if (training.Any(x => p.EndsWith(x, StringComparison.OrdinalIgnoreCase))) return true;
            return p.EndsWith(".onnx", StringComparison.OrdinalIgnoreCase) && !p.StartsWith("Runtime/Models/", StringComparison.Ordinal);
        }

        private static IEnumerable<string> TarNames(string gzipped) => TarFiles(gzipped, _ => false).Select(f => f.Name);

        /// <summary>The regular files of a gzip'd tar, with the bytes of those <paramref name="read"/> selects (others: empty).</summary>
        private static List<(string Name, byte[] Data)> TarFiles(string gzipped, Func<string, bool> read)
        {
            var files = new List<(string, byte[])>();
            using (FileStream file = File.OpenRead(gzipped))
            using (var gzip = new GZipStream(file, CompressionMode.Decompress))
            using (var tar = new TarReader(gzip))
            {
                TarEntry? entry;
                while ((entry = tar.GetNextEntry()) != null)
                {
                    if (entry.EntryType == TarEntryType.Directory) continue;
                    byte[] data = Array.Empty<byte>();
                    if (read(entry.Name) && entry.DataStream != null)
                    {
                        using var memory = new MemoryStream();
                        entry.DataStream.CopyTo(memory);
                        data = memory.ToArray();
                    }

                    files.Add((entry.Name, data));
                }
            }

            return files;
        }

        private static byte[] Pack(Action<PackageContents, Stream, Action<int>?> write, PackageContents contents)
        {
            using (var memory = new MemoryStream())
            {
                write(contents, memory, null);
                return memory.ToArray();
            }
        }

        private static Dictionary<string, byte[]> ReadTar(byte[] gzipped)
        {
            var entries = new Dictionary<string, byte[]>(StringComparer.Ordinal);
            using (var gzip = new GZipStream(new MemoryStream(gzipped), CompressionMode.Decompress))
            using (var tar = new TarReader(gzip))
            {
                TarEntry? entry;
                while ((entry = tar.GetNextEntry()) != null)
                {
                    if (entry.EntryType == TarEntryType.Directory) continue;
                    using (var data = new MemoryStream())
                    {
                        entry.DataStream?.CopyTo(data);
                        entries.Add(entry.Name, data.ToArray());
                    }
                }
            }

            return entries;
        }

        private void Write(string relative, string text)
        {
            string path = Path.Combine(_root, relative);
            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllText(path, text);
        }

        private void Meta(string asset, string guid) => Write(asset + ".meta", $"fileFormatVersion: 2\nguid: {guid}\n");

        private bool Git(string arguments)
        {
            try
            {
                var info = new ProcessStartInfo("git", arguments) { WorkingDirectory = _root, UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true };
                using (Process? p = Process.Start(info))
                {
                    if (p == null) return false;
                    p.StandardOutput.ReadToEnd();
                    p.StandardError.ReadToEnd();
                    p.WaitForExit();
                    return p.ExitCode == 0;
                }
            }
            catch (System.ComponentModel.Win32Exception)
            {
                return false;
            }
        }
    }
}
