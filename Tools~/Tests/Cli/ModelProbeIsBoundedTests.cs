using System.IO;
using DeltaInterpolator.Tests.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Every verb that loads a model refuses one outside the contract before running it: <c>check</c> reports the
    /// operator as an error (exit 2) and <c>bake</c>, <c>score</c>, <c>speed</c> print one line (exit 2) — none
    /// hangs on a 10^12-trip <c>Loop</c>.
    /// </summary>
    public sealed class ModelProbeIsBoundedTests
    {
        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        [Test]
        public void CheckAndEveryVerbThatLoadsAModelRefuseAHugeLoopAtOnce()
        {
            using var temp = new TempFolder();
            string model = HostileModels.WriteWithLoop(temp["loop.onnx"], 1_000_000_000_000L);
            CliRun check = CliHarness.RunWithin(60, "check", model);
            Assert.That(check.ExitCode, Is.EqualTo(2), check.ToString());
            // The table wraps long lines: compare with runs of white space made one space.
            Assert.That(System.Text.RegularExpressions.Regex.Replace(check.Stdout, @"\s+", " "), Does.Contain("operator Loop"), check.ToString());

            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "bake", Sample, "--every", "60", "--model", model, "--out", temp["o.bvh"]), "operator Loop");
            Assert.That(File.Exists(temp["o.bvh"]), Is.False);
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "speed", "--model", model, "--json", temp["s.json"]), "operator Loop");
            string data = Path.Combine(temp.Path, "data");
            Directory.CreateDirectory(data);
            File.Copy(Sample, Path.Combine(data, "a.bvh"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "score", data, "--every", "60", "--model", model), "operator Loop");
        }
    }
}
