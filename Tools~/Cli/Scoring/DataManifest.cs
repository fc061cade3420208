using System;
using System.Collections.Generic;
using System.IO;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace DeltaInterpolator.Cli.Scoring
{
    /// <summary>
    /// A folder of BVH files and its per-file facts: the data manifest format that the trainer's
    /// <c>prepare</c> reads too (<c>Training/Python~/deltainterp/datasets.py</c> owns the description; this mirrors it
    /// field for field): <c>inbetween-data.json</c> inside the folder, or a <c>NAME.json</c> whose
    /// <c>"folder"</c> names the folder relative to it; <c>defaults</c> and <c>files</c> (globs on the path
    /// relative to the folder, later matches win) with <c>from_frame</c>, <c>reference_frame</c>, <c>fps</c>,
    /// <c>map</c>, <c>skip</c> and <c>up</c> (the file's up axis: "auto", "y" or "z", as <c>--up</c>); <c>groups</c>, a regex whose group 1 names a file's subject.
    /// </summary>
    internal sealed class DataManifest
    {
        public const string FileName = "inbetween-data.json";
        private const long MaxBytes = 1 << 20;
        private static readonly HashSet<string> FileFields = new HashSet<string>(StringComparer.Ordinal) { "from_frame", "reference_frame", "fps", "map", "skip", "up" };
        private static readonly HashSet<string> TopFields = new HashSet<string>(StringComparer.Ordinal) { "folder", "licence", "defaults", "files", "groups", "comment" };

        private readonly List<KeyValuePair<string, Dictionary<string, JsonElement>>> _files = new List<KeyValuePair<string, Dictionary<string, JsonElement>>>();
        private readonly Dictionary<string, JsonElement> _defaults = new Dictionary<string, JsonElement>(StringComparer.Ordinal);
        private Regex? _groups;

        private DataManifest(string folder, string? path)
        {
            Folder = folder;
            Path = path;
        }

        /// <summary>The data folder.</summary>
        public string Folder { get; }

        /// <summary>The manifest file, or null for a folder without one.</summary>
        public string? Path { get; }

        /// <summary>One file's facts.</summary>
        public sealed class Entry
        {
            public Entry(string path, string name, string group, int fromFrame, int? referenceFrame, double? fps, string? map, Core.Retargeting.UpAxis? up = null)
            {
                Up = up;
                FilePath = path;
                Name = name;
                Group = group;
                FromFrame = fromFrame;
                ReferenceFrame = referenceFrame;
                Fps = fps;
                Map = map;
            }

            public string FilePath { get; }
            public string Name { get; }
            public string Group { get; }
            public int FromFrame { get; }
            public int? ReferenceFrame { get; }
            public double? Fps { get; }
            public string? Map { get; }
            /// <summary>The manifest's "up" for the file, or null when it names none (score's --up then applies).</summary>
            public Core.Retargeting.UpAxis? Up { get; }
        }

        /// <summary>A folder (with its optional manifest) or a manifest naming its folder.</summary>
        public static DataManifest Open(string spec)
        {
            if (Directory.Exists(spec))
            {
                string inside = System.IO.Path.Combine(spec, FileName);
                var m = new DataManifest(spec, File.Exists(inside) ? inside : null);
                if (m.Path != null) m.Read(m.Path, expectFolder: false);
                return m;
            }

            Core.IO.InputFile.Check(spec, "a folder of BVH files or a data manifest (.json)");
            var probe = new DataManifest("", spec);
            string folder = probe.Read(spec, expectFolder: true)!;
            var manifest = new DataManifest(folder, spec);
            manifest.Read(spec, expectFolder: true);
            return manifest;
        }

        /// <summary>Every BVH file under the folder (sorted, recursive) that is not skipped, excluded or held out.</summary>
        public List<Entry> Entries(IReadOnlyList<string> only)
        {
            var result = new List<Entry>();
            string root = System.IO.Path.GetFullPath(Folder);
            // Each real folder once: a directory link looping back into the folder adds nothing.
            List<string> files = DataFolderWalk.Files(root);
            string baseDir = Path == null ? root : System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(Path))!;
            foreach (string file in files)
            {
                if (!file.EndsWith(".bvh", StringComparison.OrdinalIgnoreCase)) continue;
                Core.IO.InputFile.Check(file, "BVH files (a FIFO, device or folder named .bvh is refused)");
                string name = System.IO.Path.GetRelativePath(root, file).Replace('\\', '/');
                string leaf = System.IO.Path.GetFileName(file);
                if (only.Count > 0 && !Matches(only, name, leaf)) continue;
                var settings = new Dictionary<string, JsonElement>(_defaults, StringComparer.Ordinal);
                foreach (var kv in _files)
                {
                    if (Glob(kv.Key, name) || Glob(kv.Key, leaf)) foreach (var s in kv.Value) settings[s.Key] = s.Value;
                }

                if (settings.TryGetValue("skip", out JsonElement skip) && skip.ValueKind == JsonValueKind.True) continue;
                int from = Int(settings, "from_frame") ?? 0;
                int? reference = Int(settings, "reference_frame");
                double? fps = settings.TryGetValue("fps", out JsonElement f) && f.ValueKind == JsonValueKind.Number ? f.GetDouble() : (double?)null;
                string? map = settings.TryGetValue("map", out JsonElement mp) && mp.ValueKind == JsonValueKind.String ? System.IO.Path.Combine(baseDir, mp.GetString()!) : null;
                string group = "";
                if (_groups != null)
                {
                    Match m = _groups.Match(name);
                    if (m.Success && m.Groups.Count > 1) group = m.Groups[1].Value;
                }

                Core.Retargeting.UpAxis? up = settings.TryGetValue("up", out JsonElement u) && u.ValueKind == JsonValueKind.String
                    ? Core.Retargeting.UpAxes.Parse(u.GetString()) : null;
                result.Add(new Entry(file, name, group, from, reference, fps, map, up));
            }

            return result;
        }

        private static bool Matches(IReadOnlyList<string> globs, string name, string leaf)
        {
            foreach (string g in globs) if (Glob(g, name) || Glob(g, leaf)) return true;
            return false;
        }

        /// <summary>Python's fnmatch.fnmatchcase (<see cref="FileGlob"/>): * and ? match any character ('/' too), [seq] and [!seq] sets.</summary>
        internal static bool Glob(string pattern, string text) => FileGlob.Parse(pattern).Matches(text);

        private static int? Int(Dictionary<string, JsonElement> settings, string key)
            => settings.TryGetValue(key, out JsonElement v) && v.ValueKind == JsonValueKind.Number && v.TryGetInt32(out int i) ? i : (int?)null;

        /// <returns>The folder the manifest names (when <paramref name="expectFolder"/>).</returns>
        private string? Read(string path, bool expectFolder)
        {
            // Regular files only, size-bounded before reading (a FIFO or /dev/zero never blocks or grows).
            string text = Core.IO.InputFile.ReadAllText(path, "a data manifest (.json)", MaxBytes);
            JsonDocument doc;
            try
            {
                doc = JsonDocument.Parse(text, new JsonDocumentOptions { MaxDepth = 16 });
            }
            catch (JsonException e)
            {
                throw new CliErrors.UsageException($"{path}:{(e.LineNumber ?? 0) + 1}: not valid JSON; expected a data manifest");
            }

            using (doc)
            {
                JsonElement root = doc.RootElement;
                if (root.ValueKind != JsonValueKind.Object) throw new CliErrors.UsageException($"{path}: holds no JSON object; expected a data manifest");
                foreach (JsonProperty p in root.EnumerateObject())
                {
                    if (!TopFields.Contains(p.Name)) throw new CliErrors.UsageException($"{path}: unknown field \"{TerminalText.Safe(p.Name, 80)}\"; expected folder, licence, defaults, files, groups, comment");
                }

                if (root.TryGetProperty("defaults", out JsonElement d)) Settings(path, d, _defaults);
                if (root.TryGetProperty("files", out JsonElement files))
                {
                    if (files.ValueKind != JsonValueKind.Object) throw new CliErrors.UsageException($"{path}: \"files\" is not an object; expected {{GLOB: {{setting: value}}}}");
                    foreach (JsonProperty p in files.EnumerateObject())
                    {
                        var s = new Dictionary<string, JsonElement>(StringComparer.Ordinal);
                        Settings(path, p.Value, s);
                        _files.Add(new KeyValuePair<string, Dictionary<string, JsonElement>>(p.Name, s));
                    }
                }

                if (root.TryGetProperty("groups", out JsonElement g) && g.ValueKind == JsonValueKind.String)
                {
                    try
                    {
                        _groups = new Regex(g.GetString()!, RegexOptions.None, TimeSpan.FromSeconds(1));
                    }
                    catch (ArgumentException)
                    {
                        throw new CliErrors.UsageException($"{path}: \"groups\" is not a regular expression; expected e.g. \"^(\\\\d+)_\"");
                    }
                }

                if (!expectFolder) return null;
                if (!root.TryGetProperty("folder", out JsonElement folder) || folder.ValueKind != JsonValueKind.String)
                {
                    throw new CliErrors.UsageException($"{path}: names no \"folder\"; expected a manifest with \"folder\": the data folder, relative to it");
                }

                string dir = System.IO.Path.GetFullPath(System.IO.Path.Combine(System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(path))!, folder.GetString()!));
                if (!Directory.Exists(dir)) throw new CliErrors.UsageException($"{path}: \"folder\" {TerminalText.Safe(folder.GetString()!, 200)} is not a folder ({TerminalText.Safe(dir, 300)}); expected the data folder");
                return dir;
            }
        }

        private static void Settings(string path, JsonElement element, Dictionary<string, JsonElement> into)
        {
            if (element.ValueKind != JsonValueKind.Object) throw new CliErrors.UsageException($"{path}: per-file settings that are not an object; expected {{\"from_frame\": 1, ...}}");
            foreach (JsonProperty p in element.EnumerateObject())
            {
                if (!FileFields.Contains(p.Name)) throw new CliErrors.UsageException($"{path}: unknown setting \"{TerminalText.Safe(p.Name, 80)}\"; expected from_frame, reference_frame, fps, map, skip, up");
                if (p.Name == "up" && p.Value.ValueKind != JsonValueKind.Null
                    && (p.Value.ValueKind != JsonValueKind.String || p.Value.GetString() is not ("auto" or "y" or "z")))
                {
                    throw new CliErrors.UsageException($"{path}: \"up\": {TerminalText.Safe(p.Value.GetRawText(), 40)}; expected \"auto\", \"y\" or \"z\" (or null)");
                }

                into[p.Name] = p.Value.Clone();
            }
        }
    }
}
