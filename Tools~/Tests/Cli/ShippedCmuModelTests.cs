using System.Globalization;
using System.IO;
using System.Text.Json;
using DeltaInterpolator.Tests.Retargeting;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// What the default model promises (Documentation~/model-card.md), measured through the tool a user runs:
    /// ahead of SLERP on the demo's held-out clip, and over every held-out file at keys every 15 and 30 model
    /// frames. (Measured 2026-12-02 with the longer chained third stage: 0.829 / 0.836 and 0.913 / 0.928 × SLERP in
    /// position ÷ leg and L2Q; the goals, 0.80 / 0.85 and 0.85 / 0.90, are not all reached yet: the model
    /// card says so.)
    /// </summary>
    public sealed class ShippedCmuModelTests
    {
        private string _dir = "";

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "inbetween-cmu-" + System.Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveFolder() => Directory.Delete(_dir, true);

        private static string Root => TestEnvironment.RepositoryRoot!;

        [Test]
        public void TheDemoClipIsBakedBetterThanSlerpInPositionAndRotation()
        {
            string sample = Path.Combine(Root, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");
            string json = Path.Combine(_dir, "demo.json");
            CliRun run = CliHarness.Run("bake", sample, "--every", "60", "--reference-frame", "0", "--from-frame", "1", "--out", Path.Combine(_dir, "demo.bvh"), "--json", json);
            CliHarness.AssertSuccess(run);
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            JsonElement methods = doc.RootElement.GetProperty("methods");
            Assert.That(methods.GetProperty("model").GetProperty("name").GetString(), Is.EqualTo("DeltaInterpolator-CMU"), "the default model");
            double p = methods.GetProperty("model").GetProperty("mean_position_error").GetDouble() / methods.GetProperty("slerp").GetProperty("mean_position_error").GetDouble();
            double q = methods.GetProperty("model").GetProperty("l2q").GetDouble() / methods.GetProperty("slerp").GetProperty("l2q").GetDouble();
            TestContext.WriteLine(string.Format(CultureInfo.InvariantCulture, "demo clip, keys every 15 model frames: position {0:0.000} x SLERP, L2Q {1:0.000} x SLERP", p, q));
            Assert.That(p, Is.LessThan(1.0));
            Assert.That(q, Is.LessThan(1.0));
        }

        [TestCase(60, 0.90, 0.90)]
        [TestCase(120, 1.0, 1.0)]
        public void HeldOutSubjectsAreBakedBetterThanSlerp(int every, double position, double rotation)
        {
            RetargetFixtures.RequireCmu();
            if (!Directory.Exists(Path.Combine(Root, "..", "shared", "data", "cmu-more"))) Assert.Ignore("../shared/data/cmu-more is absent; skipping the held-out scores");
            string json = Path.Combine(_dir, "heldout.json");
            CliRun run = CliHarness.Run("score", Path.Combine(Root, "Training", "Python~", "datasets", "cmu.json"), Path.Combine(Root, "Training", "Python~", "datasets", "cmu-more.json"),
                "--only", "02_*", "09_*", "13_*", "38_*", "--every", every.ToString(CultureInfo.InvariantCulture), "--json", json);
            CliHarness.AssertSuccess(run);
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            JsonElement total = doc.RootElement.GetProperty("total");
            Assert.That(total.GetProperty("files").GetInt32(), Is.EqualTo(33), "every held-out file of both folders");
            JsonElement model = total.GetProperty("methods").GetProperty("DeltaInterpolator-CMU");
            double p = model.GetProperty("position_vs_slerp").GetDouble(), q = model.GetProperty("l2q_vs_slerp").GetDouble();
            TestContext.WriteLine(string.Format(CultureInfo.InvariantCulture, "held out, keys every {0} input frames: position/leg {1:0.000} x SLERP, L2Q {2:0.000} x SLERP", every, p, q));
            Assert.That(p, Is.LessThan(position));
            Assert.That(q, Is.LessThan(rotation));
        }
    }
}
