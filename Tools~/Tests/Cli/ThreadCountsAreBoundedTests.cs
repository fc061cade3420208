using System;
using System.Globalization;
using System.IO;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// <c>bake --threads</c> is bounded by the processors, as <c>speed</c> and <c>benchmark</c> are (500 threads took
    /// 19 s, 100,000 more than 40 s and GBs), and a thread count ONNX Runtime cannot make is refused as the
    /// option or property it is, never as a broken model (2147483647 read "std::bad_alloc" against the model).
    /// </summary>
    public sealed class ThreadCountsAreBoundedTests
    {
        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        [TestCase("500")]
        [TestCase("100000")]
        [TestCase("2147483647")]
        public void BakeRefusesMoreThreadsThanProcessors(string threads)
        {
            if (Environment.ProcessorCount >= 500) Assert.Ignore("this machine has 500 processors or more");
            using var temp = new TempFolder();
            CliRun run = CliHarness.RunWithin(30, "bake", Sample, "--every", "60", "--out", temp["o.bvh"], "--threads", threads);
            string line = CliHarness.AssertOneErrorLine(run, "--threads " + threads);
            Assert.That(line, Does.Contain(Environment.ProcessorCount.ToString(CultureInfo.InvariantCulture) + " processors"));
            Assert.That(File.Exists(temp["o.bvh"]), Is.False);
        }

        [Test]
        public void TheApiNamesTheThreadCountNotTheModel()
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new OnnxRuntimeOptions { IntraOpThreads = int.MaxValue })!;
            Assert.That(e.ParamName, Is.EqualTo(nameof(OnnxRuntimeOptions.IntraOpThreads)));
            Assert.Throws<ArgumentOutOfRangeException>(() => new OnnxRuntimeOptions { IntraOpThreads = -1 });
            Assert.That(new OnnxRuntimeOptions { IntraOpThreads = Environment.ProcessorCount }.IntraOpThreads, Is.EqualTo(Environment.ProcessorCount));
        }
    }
}
