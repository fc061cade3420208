using System;
using System.IO;
using System.Text.RegularExpressions;
using DeltaInterpolator.Core.Json;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Package
{
    /// <summary>
    /// The samples <c>package.json</c> declares are what the Package Manager offers to import: each must exist
    /// under <c>Samples~</c> with a README, and the Demo sample must bring what its scene builder reads — the two
    /// clips as BVH files whose .meta names the package's BVH importer (so they import as characters with clips,
    /// with the same GUIDs in every project), its runtime and editor assemblies, and the builder's menu.
    /// </summary>
    public sealed class PackageSamplesTests
    {
        [Test]
        public void EveryDeclaredSampleExistsWithAReadme()
        {
            string root = Root();
            JsonValue package = JsonValue.Parse(File.ReadAllText(Path.Combine(root, "package.json")), "package.json");
            int count = 0;
            foreach (JsonValue sample in package.ExpectMember("samples").ExpectArray("samples"))
            {
                string path = sample.ExpectMember("path").ExpectString("path");
                Assert.That(path, Does.StartWith("Samples~/"), "samples live where Unity does not import them");
                Assert.That(File.Exists(Path.Combine(root, path, "README.md")), Is.True, path + "/README.md");
                Assert.That(sample.ExpectMember("displayName").ExpectString("displayName"), Is.Not.Empty);
                count++;
            }

            Assert.That(count, Is.GreaterThanOrEqualTo(2), "Transitions and Demo");
        }

        [Test]
        public void TheDemoSampleBringsItsClipsThroughTheBvhImporterAndItsSceneBuilder()
        {
            string root = Root();
            string demo = Path.Combine(root, "Samples~", "Demo");
            string importerGuid = Guid(File.ReadAllText(Path.Combine(root, "Editor", "Importers", "BvhImporter.cs.meta")));
            foreach (string clip in new[] { "cmu_09_12_walk_navigate.bvh", "cmu_01_01_jumps_turn.bvh" })
            {
                string meta = File.ReadAllText(Path.Combine(demo, clip + ".meta"));
                Assert.That(meta, Does.Contain("ScriptedImporter:"), clip);
                Assert.That(meta, Does.Contain($"guid: {importerGuid}, type: 3"), clip + ": imported by Editor/Importers/BvhImporter.cs");
            }

            Assert.That(File.Exists(Path.Combine(demo, "Scripts", "DeltaInterpolator.Samples.Demo.asmdef")), Is.True);
            string builder = File.ReadAllText(Path.Combine(demo, "Editor", "DemoSceneBuilder.cs"));
            Assert.That(builder, Does.Contain("[MenuItem(\"Tools/Δ-Interpolator/Build Demo Scene\")]"));
            Assert.That(File.ReadAllText(Path.Combine(demo, "README.md")), Does.Contain("*Tools → Δ-Interpolator → Build Demo Scene*"), "the README names the builder's menu");
            // The builder loads the files by these names: a rename must fail here, not in a user's Editor.
            Assert.That(builder, Does.Contain("\"cmu_09_12_walk_navigate.bvh\"").And.Contain("\"cmu_01_01_jumps_turn.bvh\""));
        }

        private static string Guid(string meta) => Regex.Match(meta, @"^guid:\s*([0-9a-f]{32})\s*$", RegexOptions.Multiline).Groups[1].Value;

        private static string Root()
        {
            if (TestEnvironment.InsideUnity) Assert.Ignore("runs under dotnet test only (inside Unity the package's Samples~ folder is not imported)");
            return TestEnvironment.RepositoryRoot ?? throw new InvalidOperationException("the repository root (package.json) was not found above the test assembly");
        }
    }
}
