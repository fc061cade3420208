using System.IO;
using System.Text.Json;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>Issue 30: <c>--every</c> in input frames (bare), model frames (<c>mf</c>) or seconds (<c>s</c>) on <c>bake</c> and <c>score</c>; hostile values refused in one line.</summary>
    public sealed class EveryVerbTests
    {
        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        private static int[] BakedKeys(TempFolder dir, string every)
        {
            string json = dir["keys-" + every + ".json"];
            CliRun run = CliHarness.Run("bake", Sample, "--every", every, "--from-frame", "1", "--reference-frame", "0", "--feet", "off", "--out", dir["out-" + every + ".bvh"], "--json", json);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("keys every 0.5 s = 15 model frames (at 30 fps) = 60 input frames (at 120 fps)"), "the spacing in all three units");
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            JsonElement keys = doc.RootElement.GetProperty("keys");
            var result = new int[keys.GetArrayLength()];
            for (int i = 0; i < result.Length; i++) result[i] = keys[i].GetInt32();
            return result;
        }

        [Test]
        public void SecondsModelFramesAndInputFramesBakeTheSameKeys()
        {
            if (!File.Exists(Sample)) Assert.Ignore($"{Sample} absent; skipping.");
            using var dir = new TempFolder();
            int[] input = BakedKeys(dir, "60");
            Assert.That(BakedKeys(dir, "15mf"), Is.EqualTo(input));
            Assert.That(BakedKeys(dir, "0.5s"), Is.EqualTo(input));
            TestContext.WriteLine($"{input.Length} keys: {string.Join(",", input)}");
        }

        [TestCase("0")]
        [TestCase("-15")]
        [TestCase("1.5")]
        [TestCase("abc")]
        [TestCase("0.5ss")]
        [TestCase("\u001b[2J")]
        [TestCase("99999999999999999999")]
        public void HostileSpacingsAreRefusedInOneLine(string every)
        {
            using var dir = new TempFolder();
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", Sample, "--every", every, "--out", dir["out.bvh"]), "--every");
            CliHarness.AssertOneErrorLine(CliHarness.Run("score", dir.Path, "--every", every), "--every");
            Assert.That(File.Exists(dir["out.bvh"]), Is.False);
        }

        [Test]
        public void ASpacingBelowTwoModelFramesIsRefusedNamingTheFile()
        {
            if (!File.Exists(Sample)) Assert.Ignore($"{Sample} absent; skipping.");
            using var dir = new TempFolder();
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", Sample, "--every", "1mf", "--out", dir["out.bvh"]), "leaves no model frame to fill");
        }
    }
}
