using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Bvh
{
    public class BvhWriterFileTests
    {
        [Test]
        public void AFailingWriteLeavesTheOldFileByteIdentical()
        {
            using (var fs = new FileSystemFixtures())
            {
                string path = fs["out.bvh"];
                BvhWriter.Write(BvhReader.Parse(BvhSamples.TwoJoints, "two.bvh"), path);
                byte[] before = File.ReadAllBytes(path);
                Assert.That(BvhReader.Read(path).Skeleton.Names, Is.EqualTo(new[] { "Hips", "Spine" }));

                // Joints out of depth-first order: the writer throws after it has started.
                var skeleton = new Skeleton(new[] { "a", "b", "c", "d" }, new[] { -1, 0, 0, 1 }, new double[12]);
                var rotations = new[] { BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation };
                var bad = new BvhAnimation(MotionClip.CreateRestPose(skeleton, 1, 0.1), new[] { rotations, rotations, rotations, rotations }, null, "bad");
                Assert.That(() => BvhWriter.Write(bad, path), Throws.ArgumentException);
                Assert.That(File.ReadAllBytes(path), Is.EqualTo(before));
                Assert.That(fs.Files, Is.EqualTo(new[] { path }), "no temporary file left");
            }
        }
    }
}
