using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using DeltaInterpolator.Core.Json;

namespace DeltaInterpolator.Cli.Packaging
{
    /// <summary>One importable file or folder of the package and the GUID its <c>.meta</c> gives it.</summary>
    public sealed class PackageAsset
    {
        public PackageAsset(string path, bool isFolder, string guid)
        {
            Path = path;
            IsFolder = isFolder;
            Guid = guid;
        }

        /// <summary>Path relative to the package root, '/'-separated.</summary>
        public string Path { get; }

        /// <summary>True for a folder (its <c>.unitypackage</c> entry has no <c>asset</c> file).</summary>
        public bool IsFolder { get; }

        /// <summary>The 32-hex-digit GUID from the asset's <c>.meta</c>.</summary>
        public string Guid { get; }
    }

    /// <summary>
    /// What goes into the package archives, read from a repository: the files git would commit (or, outside
    /// git, the tree minus build and data folders), split by Unity's rule into importable assets (no path
    /// component starting with '.' or ending with '~'), each with its <c>.meta</c>, and the hidden UPM
    /// layout folders the Package Manager itself reads (<c>Samples~</c> to import samples,
    /// <c>Documentation~</c>). Everything else hidden (<c>Tools~</c>, <c>UnityPackage/HostProject~</c>,
    /// <c>.ci</c>, …) stays out.
    /// </summary>
    public sealed class PackageContents
    {
        /// <summary>Hidden folders at the package root that a UPM package carries (Package Manager reads them).</summary>
        public static readonly IReadOnlyList<string> CarriedHiddenFolders = new[] { "Samples~", "Documentation~" };

        // Never packed even outside git (where .gitignore cannot say so): outputs, data and caches.
        private static readonly string[] NeverPacked = { "runs", "node_modules", "__pycache__", "out" };

        // A .meta or package.json is a few hundred bytes; read at most this much of one.
        private const long MaxMetaBytes = 1 << 20;

        private static readonly Regex GuidLine = new Regex(@"^guid:\s*([0-9a-f]{32})\s*$", RegexOptions.Multiline);

        private PackageContents(string root, string name, string version, List<string> files, List<PackageAsset> assets)
        {
            Root = root;
            Name = name;
            Version = version;
            Files = files;
            Assets = assets;
        }

        /// <summary>The repository (package) root.</summary>
        public string Root { get; }

        /// <summary>The package name from <c>package.json</c>.</summary>
        public string Name { get; }

        /// <summary>The package version from <c>package.json</c>.</summary>
        public string Version { get; }

        /// <summary>Every file of the UPM archive (assets, their metas, carried hidden folders), sorted, '/'-separated.</summary>
        public IReadOnlyList<string> Files { get; }

        /// <summary>Every importable file and folder with its GUID, sorted by path.</summary>
        public IReadOnlyList<PackageAsset> Assets { get; }

        /// <summary>True when Unity imports <paramref name="path"/> (no hidden component).</summary>
        public static bool Importable(string path) => path.Split('/').All(c => c.Length > 0 && !c.StartsWith(".", StringComparison.Ordinal) && !c.EndsWith("~", StringComparison.Ordinal));

        /// <summary>
        /// Reads the package at <paramref name="root"/>.
        /// </summary>
        /// <exception cref="CliErrors.UsageException">No package.json, or an importable file without a .meta, or two metas with one GUID.</exception>
        public static PackageContents Read(string root)
        {
            root = Path.GetFullPath(root);
            string manifest = Path.Combine(root, "package.json");
            Core.IO.InputFile.Check(manifest, "the root of a Unity package (a folder with package.json)");

            (string name, string version) = ReadManifest(manifest);
            PackagePaths.CheckManifest(manifest, name, version);
            List<string> all = GitFiles(root) ?? WalkFiles(root);
            var present = all.Where(f => File.Exists(Path.Combine(root, f)) || Core.IO.FileNode.Of(Path.Combine(root, f)).Kind is not (Core.IO.FileNodeKind.Missing or Core.IO.FileNodeKind.Directory))
                .Distinct(StringComparer.Ordinal).ToList();

            var importable = present.Where(Importable).ToList();
            var metas = new HashSet<string>(importable.Where(f => f.EndsWith(".meta", StringComparison.Ordinal)), StringComparer.Ordinal);
            var assetFiles = importable.Where(f => !f.EndsWith(".meta", StringComparison.Ordinal)).ToList();
            var folders = new SortedSet<string>(StringComparer.Ordinal);
            foreach (string f in assetFiles)
            {
                for (string d = Parent(f); d.Length > 0; d = Parent(d)) folders.Add(d);
            }

            var assets = new List<PackageAsset>();
            var byGuid = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach ((string path, bool folder) in assetFiles.Select(f => (f, false)).Concat(folders.Select(d => (d, true))).OrderBy(p => p.Item1, StringComparer.Ordinal))
            {
                string meta = path + ".meta";
                if (!metas.Contains(meta))
                {
                    throw new CliErrors.UsageException($"{Path.Combine(root, path)}: has no .meta; expected one beside every importable file and folder (run python3 Tools~/metas.py and commit the metas)");
                }

                PackagePaths.CheckFile(root, meta); // a named pipe would block the read forever
                Match m = GuidLine.Match(Core.IO.InputFile.ReadAllText(Path.Combine(root, meta), "a Unity .meta file", MaxMetaBytes));
                if (!m.Success)
                {
                    throw new CliErrors.UsageException($"{Path.Combine(root, meta)}: has no guid line; expected 'guid: ' and 32 hex digits");
                }

                string guid = m.Groups[1].Value;
                if (byGuid.TryGetValue(guid, out string? other))
                {
                    throw new CliErrors.UsageException($"{Path.Combine(root, meta)}: GUID {guid} is also the GUID of {other}.meta; expected a unique GUID per asset (delete one .meta and run python3 Tools~/metas.py)");
                }

                byGuid.Add(guid, path);
                assets.Add(new PackageAsset(path, folder, guid));
            }

            var files = importable.Concat(present.Where(Carried)).Distinct(StringComparer.Ordinal).OrderBy(f => f, StringComparer.Ordinal).ToList();
            foreach (string file in files)
            {
                // Before a byte is written: names an archive holds as they are, files that are files of this package.
                PackagePaths.CheckEntry(root, file, "package/");
                PackagePaths.CheckFile(root, file);
            }

            return new PackageContents(root, name, version, files, assets);
        }

        private static bool Carried(string path)
        {
            foreach (string folder in CarriedHiddenFolders)
            {
                if (path.StartsWith(folder + "/", StringComparison.Ordinal))
                {
                    string rest = path.Substring(folder.Length + 1);
                    return rest.Length > 0 && Importable(rest);
                }
            }

            return false;
        }

        private static (string, string) ReadManifest(string manifest)
        {
            // A malformed file throws DataFormatException (FILE:LINE: …), which the CLI reports as bad input.
            IReadOnlyDictionary<string, JsonValue> obj = JsonValue.Parse(Core.IO.InputFile.ReadAllText(manifest, "a UPM package.json", MaxMetaBytes), manifest).ExpectObject("package.json");
            string name = obj.TryGetValue("name", out JsonValue? n) ? n.ExpectString("name") : "";
            string version = obj.TryGetValue("version", out JsonValue? v) ? v.ExpectString("version") : "";
            if (name.Length == 0 || version.Length == 0)
            {
                throw new CliErrors.UsageException($"{manifest}: no \"name\" or \"version\"; expected a UPM manifest with both");
            }

            return (name, version);
        }

        private static string Parent(string path)
        {
            int slash = path.LastIndexOf('/');
            return slash < 0 ? "" : path.Substring(0, slash);
        }

        private static List<string>? GitFiles(string root)
        {
            if (!Directory.Exists(Path.Combine(root, ".git")) && !File.Exists(Path.Combine(root, ".git"))) return null;
            try
            {
                var info = new ProcessStartInfo("git", "ls-files -z --cached --others --exclude-standard")
                {
                    WorkingDirectory = root,
                    RedirectStandardOutput = true,
                    RedirectStandardError = true,
                    UseShellExecute = false,
                };
                using (Process? p = Process.Start(info))
                {
                    if (p == null) return null;
                    string output = p.StandardOutput.ReadToEnd();
                    p.StandardError.ReadToEnd();
                    p.WaitForExit();
                    if (p.ExitCode != 0) return null;
                    return output.Split('\0', StringSplitOptions.RemoveEmptyEntries).ToList();
                }
            }
            catch (System.ComponentModel.Win32Exception)
            {
                return null; // no git on PATH: walk the tree instead
            }
        }

        private static List<string> WalkFiles(string root)
        {
            var files = new List<string>();
            var pending = new Stack<string>();
            pending.Push(root);
            while (pending.Count > 0)
            {
                string dir = pending.Pop();
                foreach (string sub in Directory.GetDirectories(dir))
                {
                    string name = Path.GetFileName(sub);
                    if (name == ".git" || Array.IndexOf(NeverPacked, name) >= 0 || name.StartsWith(".", StringComparison.Ordinal)) continue;
                    if (name.EndsWith("~", StringComparison.Ordinal) && !(dir == root && CarriedHiddenFolders.Contains(name))) continue;
                    pending.Push(sub);
                }

                foreach (string file in Directory.GetFiles(dir))
                {
                    string name = Path.GetFileName(file);
                    if (name.EndsWith(".pyc", StringComparison.Ordinal)) continue;
                    files.Add(Path.GetRelativePath(root, file).Replace(Path.DirectorySeparatorChar, '/'));
                }
            }

            return files;
        }
    }
}
