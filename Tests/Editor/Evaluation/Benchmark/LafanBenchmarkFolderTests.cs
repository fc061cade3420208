using System;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Evaluation.Benchmark;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Benchmark
{
    /// <summary>
    /// <see cref="LafanBenchmarkFolder"/>: which files of a folder the benchmark scores and learns statistics
    /// from, and the folders it refuses before any work.
    /// </summary>
    [TestFixture]
    public sealed class LafanBenchmarkFolderTests
    {
        private string _dir = "";

        [SetUp]
        public void SetUp()
        {
            _dir = Path.Combine(Path.GetTempPath(), "lafan-folder-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(_dir, true);

        [Test]
        public void TestAndTrainingFilesAreSplitBySubject()
        {
            foreach (string name in new[] { "walk1_subject5.bvh", "run1_subject1.bvh", "jump1_subject4.bvh", "notes.txt" })
            {
                File.WriteAllText(Path.Combine(_dir, name), "x");
            }

            LafanBenchmarkFolder folder = LafanBenchmarkFolder.Open(_dir);
            Assert.That(folder.TestFiles, Is.EqualTo(new[] { Path.Combine(_dir, "walk1_subject5.bvh") }));
            Assert.That(folder.TrainingFiles, Has.Count.EqualTo(2));
            Assert.That(folder.TestBytes(), Is.EqualTo(1));
        }

        [Test]
        public void AFolderWithoutTestFilesIsRefused()
        {
            File.WriteAllText(Path.Combine(_dir, "run1_subject1.bvh"), "x");
            var e = Assert.Throws<DataFormatException>(() => LafanBenchmarkFolder.Open(_dir))!;
            Assert.That(e.Message, Is.EqualTo(_dir + ": no *_subject5.bvh files; expected the LaFAN1 test files (subject 5) in --data"));
        }

        [Test]
        public void AFileOrAMissingFolderIsRefused()
        {
            string file = Path.Combine(_dir, "file.txt");
            File.WriteAllText(file, "x");
            Assert.That(Assert.Throws<InputPathException>(() => LafanBenchmarkFolder.Open(file))!.Message, Does.Contain("is a file, not a directory"));
            Assert.That(Assert.Throws<InputPathException>(() => LafanBenchmarkFolder.Open(Path.Combine(_dir, "none")))!.Message, Does.Contain("no such directory"));
        }
    }
}
