using System.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Settings files a command reads — data manifests, key lists (<c>--keys @FILE</c>), manifests' joint maps — are
    /// inputs: <c>--force</c> allows replacing an existing output, never an input, so no output may land on one.
    /// </summary>
    public sealed class SettingsFilesAreInputsTests
    {
        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        [Test]
        public void ScoreNeverWritesItsJsonOverTheManifestItReads()
        {
            using var temp = new TempFolder();
            string data = Path.Combine(temp.Path, "data");
            // A clip the default model can bake, so that without the refusal the report really replaces the manifest.
            string clip = temp.Write("data/01_01.bvh", File.ReadAllText(Sample));
            string inside = temp.Write("data/inbetween-data.json", "{\"defaults\": {\"from_frame\": 1}}");
            string named = temp.Write("cmu.json", "{\"folder\": \"data\", \"defaults\": {\"from_frame\": 1, \"map\": \"map.json\"}}");
            string map = temp.Write("map.json", "{}");
            byte[] insideBefore = File.ReadAllBytes(inside), namedBefore = File.ReadAllBytes(named), mapBefore = File.ReadAllBytes(map);

            // The folder's own manifest, a manifest naming its folder, and the joint map a manifest names.
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", data, "--every", "60", "--json", inside, "--force"), "is also an input");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", named, "--every", "60", "--json", named, "--force"), "is also an input");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", named, "--every", "60", "--json", map, "--force"), "is also an input");
            Assert.That(File.ReadAllBytes(inside), Is.EqualTo(insideBefore));
            Assert.That(File.ReadAllBytes(named), Is.EqualTo(namedBefore));
            Assert.That(File.ReadAllBytes(map), Is.EqualTo(mapBefore));

            // A folder without a manifest: a report named inbetween-data.json there would become its manifest.
            File.Delete(inside);
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", data, "--every", "60", "--json", inside), "is also an input");
            Assert.That(File.Exists(inside), Is.False);
            Assert.That(File.Exists(clip), Is.True);
        }

        [Test]
        public void BakeAndPreviewNeverWriteOverTheKeyListTheyRead()
        {
            using var temp = new TempFolder();
            string keys = temp.Write("keys.txt", "1, 61\n121\n");
            byte[] before = File.ReadAllBytes(keys);
            string output = temp["out.bvh"];
            foreach (string option in new[] { "--json", "--out", "--preview" })
            {
                string[] args = option == "--out"
                    ? new[] { "bake", Sample, "--keys", "@" + keys, "--out", keys, "--force" }
                    : new[] { "bake", Sample, "--keys", "@" + keys, "--out", output, option, keys, "--force" };
                CliHarness.AssertOneErrorLine(CliHarness.Run(args), "is also an input");
                Assert.That(File.ReadAllBytes(keys), Is.EqualTo(before), option);
            }

            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", Sample, "--keys", "@" + keys, "--out", keys, "--force"), "is also an input");
            Assert.That(File.ReadAllBytes(keys), Is.EqualTo(before), "preview --out");
            Assert.That(File.Exists(output), Is.False, "refused before any work");
        }
    }
}
