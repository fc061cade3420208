using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// <see cref="FootContactMeasureTests"/>'s measure on files a change to the bake's foot locker may be chosen by:
    /// the three LaFAN1 files of <see cref="FootLockingAnalysisTests"/> (training subject 1) and four CMU walks and runs
    /// of training subjects (07, 08, 35; never the held-out 02, 09, 13, 38 or LaFAN1 subject 5, which the nine-file
    /// measure reports once). Explicit: about a minute
    /// (<c>dotnet test Tools~/Tests/DeltaInterpolator.Tests.csproj --filter FullyQualifiedName~FootLockDevelopmentMeasureTests</c>).
    /// </summary>
    [TestFixture]
    [Explicit("measurement for tuning the bake's foot locker: model bakes of seven files")]
    public sealed class FootLockDevelopmentMeasureTests
    {
        private static readonly string[] Files =
        {
            "lafan1/walk4_subject1", "lafan1/obstacles1_subject1", "lafan1/ground1_subject1",
            "cmu/07_01", "cmu/08_01", "cmu-more/35_01", "cmu-more/35_17",
        };

        [TestCase(15)]
        [TestCase(30)]
        public void DevelopmentFilesLockedWithTheContactSource(int modelFrames) => FootContactMeasureTests.Measure(Files, modelFrames, "development files");
    }
}
