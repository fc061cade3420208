using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Tests.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Benchmark
{
    // Beside the Evaluation tests, not in Tests/Runtime/IO/InputFileTests: the runtime test assembly does not
    // reference DeltaInterpolator.Evaluation (an Editor-only assembly), so Unity could not compile it there.
    public class BenchmarkStatisticsInputTests
    {
        [Test]
        public void AFolderGivenAsStatisticsIsNamedAsSuch()
        {
            using (var fs = new FileSystemFixtures())
            {
                Assert.That(Assert.Throws<InputPathException>(() => BenchmarkStatistics.Load(fs.Folder))!.Message, Does.StartWith(fs.Folder + ": is a directory; expected a statistics JSON"));
            }
        }
    }
}
