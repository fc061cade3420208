using DeltaInterpolator.Evaluation.Baking;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Baking
{
    /// <summary>
    /// <c>score</c>'s totals: errors weighted by non-key frames, foot skating by planted (frame, joint) pairs
    /// (a file with no planted foot adds nothing to it), ratios to the last method (SLERP).
    /// </summary>
    [TestFixture]
    public sealed class ScoreSheetTests
    {
        [Test]
        public void TotalsWeighErrorsByFramesAndSkatingByContactSamples()
        {
            var sheet = new ScoreSheet(new[] { "Model", "SLERP" });
            sheet.Add(new ScoreRow("a.bvh", "01", 100, 90, new[] { 0.02, 0.04 }, new[] { 0.2, 0.4 }, new[] { 0.1, 0.3 }, 30, 0.05));
            sheet.Add(new ScoreRow("b.bvh", "01", 300, 95, new[] { 0.06, 0.08 }, new[] { 0.6, 0.8 }, new[] { 0.5, 0.7 }, 10, 0.01));
            sheet.Add(new ScoreRow("c.bvh", "02", 100, 80, new[] { 0.01, 0.02 }, new[] { 0.1, 0.2 }, new[] { 0.0, 0.0 }, 0, double.NaN));
            ScoreTotal all = sheet.Total();
            Assert.That(all.Files, Is.EqualTo(3));
            Assert.That(all.Frames, Is.EqualTo(500));
            Assert.That(all.Errors.PositionPerLeg[0], Is.EqualTo((0.02 * 100 + 0.06 * 300 + 0.01 * 100) / 500).Within(1e-12));
            Assert.That(all.Errors.L2QRatio(0), Is.EqualTo((0.2 * 100 + 0.6 * 300 + 0.1 * 100) / (0.4 * 100 + 0.8 * 300 + 0.2 * 100)).Within(1e-12));
            Assert.That(all.Errors.ContactSamples, Is.EqualTo(40));
            Assert.That(all.Errors.FootSkating[0], Is.EqualTo((0.1 * 30 + 0.5 * 10) / 40).Within(1e-12));
            Assert.That(all.Errors.FootSkating[1], Is.EqualTo((0.3 * 30 + 0.7 * 10) / 40).Within(1e-12));
            Assert.That(all.Errors.TruthFootSkating, Is.EqualTo((0.05 * 30 + 0.01 * 10) / 40).Within(1e-12));
            ScoreTotal second = sheet.Total(sheet.Groups()["02"]);
            Assert.That(second.Errors.ContactSamples, Is.EqualTo(0));
            Assert.That(double.IsNaN(second.Errors.FootSkating[0]), Is.True, "no planted foot: no skating, not 0");
        }

        [Test]
        public void ANonFiniteErrorIsRefusedNamingTheFile()
        {
            var e = Assert.Throws<System.ArgumentException>(() => new ScoreRow("bad.bvh", "", 10, 1, new[] { double.NaN, 1.0 }, new[] { 1.0, 1.0 }));
            Assert.That(e!.Message, Does.Contain("bad.bvh"));
        }
    }
}
