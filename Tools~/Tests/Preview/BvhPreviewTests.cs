using System;
using System.IO;
using DeltaInterpolator.Core;
using DeltaInterpolator.Preview;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Preview
{
    /// <summary>
    /// <see cref="BvhPreview"/>: the scene the preview verb shows, built from BVH files — a frame range cut
    /// from every file, keys counted from the range's start, and files that cannot play together refused
    /// with the file and what to do.
    /// </summary>
    public sealed class BvhPreviewTests
    {
        private string _dir = "";

        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_01_01_jumps_turn.bvh");

        [SetUp]
        public void SetUp()
        {
            _dir = Path.Combine(Path.GetTempPath(), "bvh-preview-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(_dir, true);

        [Test]
        public void ARangeIsCutFromEveryFileAndKeysCountFromItsStart()
        {
            PreviewScene scene = BvhPreview.Build(new[] { ("Truth", Sample), ("Other", Sample) }, (10, 19), new[] { 12, 15 }, firstIsTruth: true);
            Assert.That(scene.Tracks.Count, Is.EqualTo(2));
            Assert.That(scene.FrameCount, Is.EqualTo(10));
            Assert.That(scene.KeyFrames, Is.EqualTo(new[] { 2, 5 }));
            Assert.That(scene.GroundTruthTrack, Is.EqualTo(0));
            Assert.That(scene.Title, Is.EqualTo("cmu_01_01_jumps_turn.bvh, frames 10–19"));
        }

        [Test]
        public void AKeyOutsideTheShownFramesIsRefused()
        {
            var e = Assert.Throws<DataFormatException>(() => BvhPreview.Build(new[] { ("A", Sample) }, (10, 19), new[] { 12, 500 }, false))!;
            Assert.That(e.Message, Is.EqualTo("--keys: key frame 500 is outside the shown frames 10..19 (--frames); expected key frames inside them"));
        }

        [Test]
        public void AnotherFrameRateIsRefusedNamingBothFiles()
        {
            string slower = Path.Combine(_dir, "slower.bvh");
            File.WriteAllText(slower, File.ReadAllText(Sample).Replace("Frame Time: .0083333", "Frame Time: .0333333", StringComparison.Ordinal));
            var e = Assert.Throws<DataFormatException>(() => BvhPreview.Build(new[] { ("A", Sample), ("B", slower) }, null, Array.Empty<int>(), false))!;
            Assert.That(e.Message, Does.StartWith(slower + ": 30 fps where " + Sample + " has 120 fps"));
            Assert.That(e.Message, Does.EndWith("expected one frame rate in every file"));
        }

        [Test]
        public void ARangeThatStartsAfterTheFileIsRefused()
        {
            var e = Assert.Throws<DataFormatException>(() => BvhPreview.Build(new[] { ("A", Sample) }, (5000, 5010), Array.Empty<int>(), false))!;
            Assert.That(e.Message, Is.EqualTo(Sample + ": --frames starts at 5000 but the file has 901 frames; expected a start below 901"));
        }
    }
}
