using System;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// The same motion on two differently built rigs bakes to the same world motion through <c>bake --map</c>
    /// (issue 15): the demo clip as shipped, and as a BVH of another rig (renamed joints read through a JSON map
    /// file, other local bone frames, metres, XYZ Euler channels), both baked by the command line with the
    /// model and with SLERP (the BVH it writes) — every joint's world position agrees to 1e-3 of a leg length.
    /// </summary>
    public sealed class TwoRigBakeVerbTests
    {
        private string _dir = "";

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "inbetween-tworig-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveFolder() => Directory.Delete(_dir, true);

        [Test]
        public void BakeMapBakesAnotherRigToTheSameWorldMotion()
        {
            MotionClip original = TwoRigBakeTests.DemoWalk();
            string rigA = Path.Combine(_dir, "rig-a.bvh");
            BvhWriter.Write(BvhAnimation.ForSkeleton(original, rigA), rigA);
            ModelContract contract;
            using (Inbetweener model = TwoRigBakeTests.ShippedModel()) contract = model.Contract;
            var mapped = (MappedRig)RigRetargeting.For(contract, original, rigA, referenceFrame: 0);
            (MotionClip rebuilt, string json) = TwoRigBakeTests.Rebuild(original, mapped.Map);
            string rigB = Path.Combine(_dir, "rig-b.bvh");
            int j = rebuilt.Skeleton.JointCount;
            var channels = new BvhChannel[j][];
            for (int i = 0; i < j; i++)
            {
                channels[i] = i == 0
                    ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Xrotation, BvhChannel.Yrotation, BvhChannel.Zrotation }
                    : new[] { BvhChannel.Xrotation, BvhChannel.Yrotation, BvhChannel.Zrotation };
            }

            BvhWriter.Write(new BvhAnimation(rebuilt, channels, null, rigB), rigB);
            string map = Path.Combine(_dir, "rig-b-map.json");
            File.WriteAllText(map, json);

            double leg = mapped.LegLength;
            foreach (string method in new[] { "model", "slerp" })
            {
                string outA = Path.Combine(_dir, method + "-a.bvh"), outB = Path.Combine(_dir, method + "-b.bvh");
                CliHarness.AssertSuccess(CliHarness.Run("bake", rigA, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--method", method, "--out", outA));
                CliHarness.AssertSuccess(CliHarness.Run("bake", rigB, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--map", map, "--method", method, "--out", outB));
                double[] a = TwoRigBakeTests.World(BvhReader.Read(outA).Motion);
                double[] b = TwoRigBakeTests.World(BvhReader.Read(outB).Motion);
                Assert.That(b.Length, Is.EqualTo(a.Length));
                double worst = 0;
                for (int i = 0; i < a.Length; i++) worst = Math.Max(worst, Math.Abs(a[i] - b[i] / 0.01));
                TestContext.WriteLine($"bake --map --method {method}: largest world position difference between the rigs {worst / leg:E2} leg lengths");
                Assert.That(worst / leg, Is.LessThan(1e-3), method);
            }
        }
    }
}
