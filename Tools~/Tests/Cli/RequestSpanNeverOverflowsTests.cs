using System.IO;
using System.Text.RegularExpressions;
using DeltaInterpolator.Core.Inference;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// A request's span P + n is checked without integer overflow: <c>check --gap 2147483638</c> (P = 10) wrapped to
    /// a negative sum below the model's largest frame index and passed with exit 0.
    /// </summary>
    public sealed class RequestSpanNeverOverflowsTests
    {
        private static string Tiny => Path.Combine(TestEnvironment.RepositoryRoot!, "Tests", "Fixtures~", "tiny-model.onnx");

        [TestCase("10", "2147483638")]
        [TestCase("2147483647", "2147483647")]
        [TestCase("2147483000", "1000")]
        public void CheckRefusesAGapWhoseSpanOverflows(string past, string gap)
        {
            CliRun run = CliHarness.RunWithin(60, "check", Tiny, "--past", past, "--gap", gap);
            Assert.That(run.ExitCode, Is.EqualTo(2), run.ToString());
            string text = Regex.Replace(run.Stdout, @"\s+", " ");
            Assert.That(text, Does.Contain("P + n = " + past + " + " + gap + " = " + (long.Parse(past) + long.Parse(gap))), run.ToString());
            Assert.That(text, Does.Contain("exceeds the model's largest frame index"), run.ToString());
        }

        [Test]
        public void TheCheckOfARequestCountsInLong()
        {
            var report = new ModelCheckReport();
            ModelContract contract = ModelContract.FromMetadata(Tiny, OnnxMetadataReader.Read(Tiny), new ModelCheckReport())!;
            ModelChecks.Request(contract, 10, int.MaxValue - 9, report);
            Assert.That(report.HasErrors, Is.True, "P + n = 2^31 + 0 wraps to a negative int");
        }
    }
}
