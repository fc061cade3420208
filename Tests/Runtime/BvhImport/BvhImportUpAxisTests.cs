using System;
using System.IO;
using System.Text;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.BvhImport;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Retargeting;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.BvhImport
{
    /// <summary>Issue 30: the .bvh importer's Up Axis (Core's <see cref="BvhClipImport"/>) stands a Z-up file on Y; files made here.</summary>
    public sealed class BvhImportUpAxisTests
    {
        private static byte[] Bvh(MotionClip motion)
        {
            // LaFAN1 names (a built-in map finds hips, head and feet), written as a file would hold them.
            var names = new string[motion.Skeleton.JointCount];
            for (int j = 0; j < names.Length; j++) names[j] = motion.Skeleton.Names[j].Substring("src_".Length);
            var skeleton = new Skeleton(names, motion.Skeleton.Parents, motion.Skeleton.Offsets);
            var clip = new MotionClip(skeleton, motion.FrameCount, motion.FrameTime, motion.LocalPositions, motion.LocalRotations);
            var channels = new BvhChannel[names.Length][];
            for (int j = 0; j < channels.Length; j++)
            {
                channels[j] = j == 0
                    ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation }
                    : new[] { BvhChannel.Zrotation, BvhChannel.Xrotation, BvhChannel.Yrotation };
            }

            var text = new StringWriter();
            BvhWriter.Write(new BvhAnimation(clip, channels, null, "walk.bvh"), text);
            return Encoding.UTF8.GetBytes(text.ToString());
        }

        private static double Largest(float[] a, float[] b)
        {
            Assert.That(b.Length, Is.EqualTo(a.Length));
            double worst = 0;
            for (int i = 0; i < a.Length; i++) worst = Math.Max(worst, Math.Abs(a[i] - b[i]));
            return worst;
        }

        [TestCase(true, UpAxis.Auto)]
        [TestCase(true, UpAxis.Z)]
        [TestCase(false, UpAxis.Auto)]
        [TestCase(false, UpAxis.Z)]
        public void AZUpFileImportsAsTheWalkAuthoredYUp(bool restSkeletonZUp, UpAxis up)
        {
            Skeleton model = RetargetFixtures.Lafan1();
            MotionClip walk = UpAxisFixtures.Walk(UpAxisFixtures.Standing(model, QuaternionD.Identity), 90, 1.0 / 30.0);
            BvhImportResult y = BvhClipImport.Import(Bvh(walk), "walk.bvh");
            Assert.That(y.Turned, Is.False, y.UpAxis);
            MotionClip zUp = restSkeletonZUp ? UpAxisFixtures.OnZUpSkeleton(walk) : UpAxisFixtures.InZUpWorld(walk);
            BvhImportResult z = BvhClipImport.Import(Bvh(zUp), "walk.bvh", 0, up);
            TestContext.WriteLine(z.UpAxis);
            Assert.That(z.Turned, Is.True);
            Assert.That(z.MetresPerUnit, Is.EqualTo(y.MetresPerUnit).Within(1e-9), "the unit is told from the stood skeleton");
            double positions = Largest(y.LocalPositions, z.LocalPositions), rotations = Largest(y.LocalRotations, z.LocalRotations);
            TestContext.WriteLine($"largest difference from the Y-up import: positions {positions:E2} m, rotation components {rotations:E2}");
            Assert.That(positions, Is.LessThan(1e-4));
            Assert.That(rotations, Is.LessThan(1e-4));
        }

        [Test]
        public void ForcingYKeepsAZUpFileAsItIs()
        {
            Skeleton model = RetargetFixtures.Lafan1();
            MotionClip walk = UpAxisFixtures.Walk(UpAxisFixtures.Standing(model, QuaternionD.Identity), 90, 1.0 / 30.0);
            BvhImportResult forced = BvhClipImport.Import(Bvh(UpAxisFixtures.InZUpWorld(walk)), "walk.bvh", 0, UpAxis.Y);
            Assert.That(forced.Turned, Is.False);
        }
    }
}
