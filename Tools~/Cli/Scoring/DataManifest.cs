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
    /// <c>map</c>, <c>skip</c>, <c>up</c> (the file's up axis: "auto", "y" or "z", as <c>--up</c>) and
    /// <c>accept_reference_pose</c> (true: as <c>--accept-reference-pose</c> for that file); <c>groups</c>, a regex whose group 1 names a file's subject. Both readers
    /// refuse the same values with the same messages; <c>Tests/Fixtures~/manifests</c> holds fixtures that both
    /// test suites read to the same files, settings and refusals (<c>ManifestFixtureTests</c>, <c>test_manifest_fixtures.py</c>).
    /// </summary>
    internal sealed class DataManifest
    {
        public const string FileName = "inbetween-data.json";
        private const long MaxBytes = 1 << 20;
        private static readonly HashSet<string> FileFields = new HashSet<string>(StringComparer.Ordinal) { "from_frame", "reference_frame", "fps", "map", "skip", "up", "accept_reference_pose" };
        private static readonly HashSet<string> TopFields = new HashSet<string>(StringComparer.Ordinal) { "folder", "licence", "defaults", "files", "groups", "comment" };

        private readonly List<KeyValuePair<string, Dictionary<string, JsonElement>>> _files = new List<KeyValuePair<string, Dictionary<string, JsonElement>>>();
        private readonly Dictionary<string, JsonElement> _defaults = new Dictionary<string, JsonElement>(StringComparer.Ordinal);
        private const string SettingsExpected = "expected {\"from_frame\": 1, ...}";
        private const string GroupsExpected = "expected e.g. \"^(\\\\d+)_\"";
        private static readonly TimeSpan GroupsTimeLimit = TimeSpan.FromSeconds(1);
        private static readonly Regex CountedRepeat = new Regex(@"^\{\d*,?\d*\}", RegexOptions.CultureInvariant);
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
            public Entry(string path, string name, string group, int fromFrame, int? referenceFrame, double? fps, string? map, Core.Retargeting.UpAxis? up = null, bool acceptReferencePose = false)
            {
                AcceptReferencePose = acceptReferencePose;
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

            /// <summary>The manifest's "accept_reference_pose" for the file (score's --accept-reference-pose applies to every file as well).</summary>
            public bool AcceptReferencePose { get; }
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
                    Match m;
                    try
                    {
                        m = _groups.Match(name);
                    }
                    catch (RegexMatchTimeoutException)
                    {
                        throw Refusal(Path!, $"\"groups\" took over {GroupsTimeLimit.TotalSeconds:0} s on {Quoted(name)}", "expected a pattern that does not backtrack catastrophically");
                    }

                    if (m.Success && m.Groups.Count > 1) group = m.Groups[1].Value;
                }

                Core.Retargeting.UpAxis? up = settings.TryGetValue("up", out JsonElement u) && u.ValueKind == JsonValueKind.String
                    ? Core.Retargeting.UpAxes.Parse(u.GetString()) : null;
                bool accept = settings.TryGetValue("accept_reference_pose", out JsonElement a) && a.ValueKind == JsonValueKind.True;
                result.Add(new Entry(file, name, group, from, reference, fps, map, up, accept));
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
                    if (!TopFields.Contains(p.Name)) throw Refusal(path, $"unknown field {Quoted(p.Name)}", "expected folder, licence, defaults, files, groups, comment");
                }

                if (root.TryGetProperty("defaults", out JsonElement d))
                {
                    if (d.ValueKind != JsonValueKind.Object) throw Refusal(path, "\"defaults\" is not an object", SettingsExpected);
                    Settings(path, d, _defaults);
                }

                if (root.TryGetProperty("files", out JsonElement files))
                {
                    if (files.ValueKind != JsonValueKind.Object) throw Refusal(path, "\"files\" is not an object", "expected {GLOB: {setting: value}}");
                    foreach (JsonProperty p in files.EnumerateObject())
                    {
                        if (p.Value.ValueKind != JsonValueKind.Object) throw Refusal(path, $"\"files\" {Quoted(p.Name)} is not an object", SettingsExpected);
                        var s = new Dictionary<string, JsonElement>(StringComparer.Ordinal);
                        Settings(path, p.Value, s);
                        _files.Add(new KeyValuePair<string, Dictionary<string, JsonElement>>(p.Name, s));
                    }
                }

                if (root.TryGetProperty("groups", out JsonElement g)) _groups = Groups(path, g);

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
            foreach (JsonProperty p in element.EnumerateObject())
            {
                if (!FileFields.Contains(p.Name)) throw Refusal(path, $"unknown setting {Quoted(p.Name)}", "expected from_frame, reference_frame, fps, map, skip, up, accept_reference_pose");
                if (p.Name == "up" && p.Value.ValueKind != JsonValueKind.Null
                    && (p.Value.ValueKind != JsonValueKind.String || p.Value.GetString() is not ("auto" or "y" or "z")))
                {
                    throw Refusal(path, $"\"up\": {Text(p.Value)}", "expected \"auto\", \"y\" or \"z\" (or null)");
                }

                if (p.Name == "accept_reference_pose" && p.Value.ValueKind is not (JsonValueKind.True or JsonValueKind.False or JsonValueKind.Null))
                {
                    throw Refusal(path, $"\"accept_reference_pose\": {Text(p.Value)}", "expected true or false (or null)");
                }

                into[p.Name] = p.Value.Clone();
            }

            // The values prepare refuses (datasets.py _check_settings), refused here too rather than ignored.
            foreach (string key in new[] { "from_frame", "reference_frame" })
            {
                if (into.TryGetValue(key, out JsonElement v) && v.ValueKind != JsonValueKind.Null
                    && !(v.ValueKind == JsonValueKind.Number && v.TryGetInt32(out int frame) && frame >= 0 && frame < 1_000_000))
                {
                    throw Refusal(path, $"\"{key}\": {Text(v)}", "expected a frame index from 0 (or null)");
                }
            }

            if (into.TryGetValue("fps", out JsonElement fps) && fps.ValueKind != JsonValueKind.Null
                && !(fps.ValueKind == JsonValueKind.Number && fps.TryGetDouble(out double rate) && rate >= 1 && rate <= 1000))
            {
                throw Refusal(path, $"\"fps\": {Text(fps)}", "expected a frame rate from 1 to 1000 (or null)");
            }

            if (into.TryGetValue("map", out JsonElement map) && map.ValueKind != JsonValueKind.Null && map.ValueKind != JsonValueKind.String)
            {
                throw Refusal(path, $"\"map\": {Text(map)}", "expected a path to a JSON joint map (or null)");
            }

            if (into.TryGetValue("skip", out JsonElement skip) && skip.ValueKind != JsonValueKind.True && skip.ValueKind != JsonValueKind.False)
            {
                throw Refusal(path, $"\"skip\": {Text(skip)}", "expected true or false");
            }
        }

        /// <summary>
        /// The <c>groups</c> regex: a string that parses and cannot backtrack catastrophically (issue 31, classes 12,
        /// 14), refused with prepare's messages. Matching keeps a time limit as well, for patterns the scan lets through.
        /// </summary>
        private static Regex Groups(string path, JsonElement groups)
        {
            if (groups.ValueKind != JsonValueKind.String)
            {
                throw Refusal(path, $"\"groups\": {Text(groups)}", "expected a regular expression (a string) whose group 1 names a file's subject, e.g. \"^(\\\\d+)_\"");
            }

            string pattern = groups.GetString()!;
            Regex regex;
            try
            {
                regex = new Regex(pattern, RegexOptions.None, GroupsTimeLimit);
            }
            catch (ArgumentException)
            {
                throw Refusal(path, "\"groups\" is not a regular expression", GroupsExpected);
            }

            if (RepeatsABacktrackingGroup(pattern))
            {
                throw Refusal(path, "\"groups\" repeats a group that holds a repetition or an alternative (catastrophic backtracking)", GroupsExpected);
            }

            return regex;
        }

        /// <summary>
        /// Whether <paramref name="pattern"/> applies *, + or {m,n} to a group that itself holds a repetition (*, +, ?,
        /// {m,n}) or an alternative (|): the shape whose matching time can grow exponentially with the text. The same
        /// scan as the trainer's <c>datasets.repeats_a_backtracking_group</c>.
        /// </summary>
        internal static bool RepeatsABacktrackingGroup(string pattern)
        {
            var risky = new Stack<bool>();
            int i = 0, n = pattern.Length;
            while (i < n)
            {
                char c = pattern[i];
                if (c == '\\')
                {
                    i += 2;
                    continue;
                }

                if (c == '[')
                {
                    int j = i + 1;
                    if (j < n && pattern[j] == '^') j++;
                    if (j < n && pattern[j] == ']') j++;
                    while (j < n && pattern[j] != ']') j += pattern[j] == '\\' ? 2 : 1;
                    i = j + 1;
                    continue;
                }

                if (c == '(')
                {
                    risky.Push(false);
                    i++;
                    if (i < n && pattern[i] == '?')
                    {
                        i++;
                        bool lookbehind = At(pattern, i, "<=") || At(pattern, i, "<!");
                        if (At(pattern, i, "P<") || (At(pattern, i, "<") && !lookbehind))
                        {
                            int close = pattern.IndexOf('>', i);
                            i = close < 0 ? n : close + 1;
                        }
                        else i += lookbehind ? 2 : 1;
                    }

                    continue;
                }

                if (c == ')')
                {
                    bool inner = risky.Count > 0 && risky.Pop();
                    i++;
                    if (RepeatAt(pattern, i) && inner) return true;
                    if (risky.Count > 0 && (inner || RepeatAt(pattern, i) || (i < n && pattern[i] == '?')))
                    {
                        risky.Pop();
                        risky.Push(true);
                    }

                    continue;
                }

                if (risky.Count > 0 && (c == '|' || c == '*' || c == '+' || c == '?' || RepeatAt(pattern, i)))
                {
                    risky.Pop();
                    risky.Push(true);
                }

                i++;
            }

            return false;
        }

        private static bool At(string text, int index, string part) => string.CompareOrdinal(text, index, part, 0, part.Length) == 0;

        private static bool RepeatAt(string pattern, int i)
            => i < pattern.Length && (pattern[i] == '*' || pattern[i] == '+' || (pattern[i] == '{' && CountedRepeat.IsMatch(pattern.Substring(i))));

        private static CliErrors.UsageException Refusal(string path, string what, string expected) => new CliErrors.UsageException($"{path}: {what}; {expected}");

        /// <summary>A value as the manifest wrote it (its JSON text), safe for a terminal.</summary>
        private static string Text(JsonElement value) => TerminalText.Safe(value.GetRawText(), 80);

        private static string Quoted(string name) => "\"" + TerminalText.Safe(name, 80) + "\"";
    }
}
