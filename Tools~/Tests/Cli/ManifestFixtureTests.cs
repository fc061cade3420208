using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.Json;
using DeltaInterpolator.Cli.Scoring;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// One manifest reader's rules for both languages (issue 26 item 5; issue 31 classes 12–14): every fixture under
    /// <c>Tests/Fixtures~/manifests</c> reads, through <c>score</c>'s reader (<see cref="DataManifest"/>), to the files,
    /// settings and refusal its <c>NAME.expected.json</c> holds — the same that <c>prepare</c>'s reader
    /// (<c>datasets.py</c>) must match in <c>test_manifest_fixtures.py</c>.
    /// </summary>
    public sealed class ManifestFixtureTests
    {
        private static string Fixtures => Path.Combine(TestEnvironment.RepositoryRoot!, "Tests", "Fixtures~", "manifests");

        private static IEnumerable<string> Cases()
        {
            string folder = Path.Combine(TestEnvironment.RepositoryRoot ?? ".", "Tests", "Fixtures~", "manifests");
            if (!Directory.Exists(folder)) return Array.Empty<string>();
            return Directory.GetFiles(folder, "*.expected.json").Select(f => Path.GetFileName(f)[..^".expected.json".Length]).OrderBy(n => n, StringComparer.Ordinal);
        }

        [Test]
        public void TheFixturesCoverSettingsAndTheRefusalsScoreUsedToMiss()
        {
            Assert.That(Cases(), Is.SupersetOf(new[] { "settings", "named", "fps-zero", "fps-negative", "fps-subnormal", "fps-beyond-double", "from-frame-fraction", "from-frame-text", "skip-text", "map-number", "groups-number", "groups-not-a-regex", "groups-catastrophic" }));
        }

        [TestCaseSource(nameof(Cases))]
        public void ScoreReadsEachFixtureManifestAsExpected(string name)
        {
            using JsonDocument expected = JsonDocument.Parse(File.ReadAllText(Path.Combine(Fixtures, name + ".expected.json")));
            string spec = Path.Combine(Fixtures, expected.RootElement.GetProperty("open").GetString()!);
            string manifest = Directory.Exists(spec) ? Path.Combine(spec, DataManifest.FileName) : spec;
            List<DataManifest.Entry> entries;
            try
            {
                entries = DataManifest.Open(spec).Entries(Array.Empty<string>());
            }
            catch (DeltaInterpolator.Cli.CliErrors.UsageException e)
            {
                Assert.That(e.Message, Does.StartWith(manifest + ":"));
                Assert.That(e.Message, Does.Not.Contain("\n"));
                string refused = e.Message.Substring(manifest.Length + 1).Trim();
                Assert.That(expected.RootElement.TryGetProperty("refused", out JsonElement refusal), Is.True, "read as refused, expected files: " + e.Message);
                Assert.That(refused, Is.EqualTo(refusal.GetString()));
                return;
            }

            Assert.That(expected.RootElement.TryGetProperty("files", out JsonElement files), Is.True, $"read {entries.Count} files, expected a refusal");
            var want = files.EnumerateArray().Select(f => Row(
                f.GetProperty("name").GetString()!, f.GetProperty("group").GetString()!, f.GetProperty("from_frame").GetInt32(),
                f.GetProperty("reference_frame").ValueKind == JsonValueKind.Null ? (int?)null : f.GetProperty("reference_frame").GetInt32(),
                f.GetProperty("fps").ValueKind == JsonValueKind.Null ? (double?)null : f.GetProperty("fps").GetDouble(),
                f.GetProperty("map").ValueKind == JsonValueKind.Null ? null : f.GetProperty("map").GetString())).ToList();
            var got = entries.Select(e => Row(e.Name, e.Group, e.FromFrame, e.ReferenceFrame, e.Fps,
                e.Map == null ? null : Path.GetRelativePath(Fixtures, e.Map).Replace('\\', '/'))).ToList();
            Assert.That(got, Is.EqualTo(want));
        }

        [TestCase("fps-zero")]
        [TestCase("fps-beyond-double")]
        [TestCase("from-frame-text")]
        [TestCase("map-number")]
        [TestCase("groups-number")]
        [TestCase("groups-catastrophic")]
        public void ScoreRefusesAFixtureInOneLineWithExit2(string name)
        {
            using JsonDocument expected = JsonDocument.Parse(File.ReadAllText(Path.Combine(Fixtures, name + ".expected.json")));
            string spec = Path.Combine(Fixtures, expected.RootElement.GetProperty("open").GetString()!);
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "score", spec, "--every", "30"), expected.RootElement.GetProperty("refused").GetString());
        }

        [Test]
        public void ScoreRefusesACatastrophicGroupsPatternBeforeMatchingALongName()
        {
            // Before: RegexMatchTimeoutException after a second per name, exit 1.
            using var folder = new TempFolder();
            folder.Write(new string('a', 200) + "b.bvh", "HIERARCHY\n");
            folder.Write(DataManifest.FileName, "{\"groups\": \"^(a|aa)+$\"}");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "score", folder.Path, "--every", "30"), "catastrophic backtracking");
        }

        private static string Row(string name, string group, int from, int? reference, double? fps, string? map)
            => string.Join(" | ", name, group, from.ToString(CultureInfo.InvariantCulture), reference?.ToString(CultureInfo.InvariantCulture) ?? "null",
                fps?.ToString("R", CultureInfo.InvariantCulture) ?? "null", map ?? "null");
    }
}
