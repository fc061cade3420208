using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Bvh
{
    public class BvhRoundTripTests
    {
        /// <summary>A random skeleton in depth-first order with random channel layouts and random motion.</summary>
        private static BvhAnimation Generate(int seed, int jointCount, int frameCount)
        {
            var random = new TestRandom(seed);
            var names = new string[jointCount];
            var parents = new int[jointCount];
            var offsets = new double[jointCount * 3];
            var channels = new BvhChannel[jointCount][];
            var endSites = new Vector3D[jointCount][];
            var path = new List<int>();
            for (int j = 0; j < jointCount; j++)
            {
                names[j] = "Joint" + j;
                if (j == 0)
                {
                    parents[j] = -1;
                }
                else
                {
                    // Depth-first order: the parent is the previous joint or one of its ancestors.
                    int pop = random.Next(0, path.Count);
                    path.RemoveRange(path.Count - pop, pop);
                    parents[j] = path[path.Count - 1];
                }

                path.Add(j);
                random.Vector(30).Write(offsets, 3 * j);
                channels[j] = RandomChannels(random, j == 0);
                endSites[j] = Array.Empty<Vector3D>();
            }

            for (int j = 0; j < jointCount; j++)
            {
                if (Array.IndexOf(parents, j) < 0) endSites[j] = new[] { random.Vector(5) };
            }

            var skeleton = new Skeleton(names, parents, offsets);
            var positions = new double[frameCount * jointCount * 3];
            var rotations = new double[frameCount * jointCount * 4];
            for (int f = 0; f < frameCount; f++)
            {
                for (int j = 0; j < jointCount; j++)
                {
                    bool hasPosition = Array.Exists(channels[j], c => !c.IsRotation());
                    bool hasRotation = Array.Exists(channels[j], c => c.IsRotation());
                    Vector3D p = hasPosition ? random.Vector(200) : new Vector3D(offsets[3 * j], offsets[3 * j + 1], offsets[3 * j + 2]);
                    p.Write(positions, (f * jointCount + j) * 3);
                    (hasRotation ? random.Rotation() : QuaternionD.Identity).Write(rotations, (f * jointCount + j) * 4);
                }
            }

            var motion = new MotionClip(skeleton, frameCount, 1.0 / 30, positions, rotations);
            return new BvhAnimation(motion, channels, endSites, "generated");
        }

        private static BvhChannel[] RandomChannels(TestRandom random, bool root)
        {
            var rotations = new List<BvhChannel> { BvhChannel.Xrotation, BvhChannel.Yrotation, BvhChannel.Zrotation };
            var positions = new List<BvhChannel> { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition };
            int layout = root ? 2 : random.Next(0, 3); // 0: rotations, 1: positions, 2: all six
            var chosen = new List<BvhChannel>();
            if (layout != 1) chosen.AddRange(rotations);
            if (layout != 0) chosen.AddRange(positions);
            for (int i = chosen.Count - 1; i > 0; i--)
            {
                int k = random.Next(0, i + 1);
                (chosen[i], chosen[k]) = (chosen[k], chosen[i]);
            }

            return chosen.ToArray();
        }

        private static void AssertSameMotion(BvhAnimation actual, BvhAnimation expected, double tolerance)
        {
            Assert.That(actual.Skeleton.Names, Is.EqualTo(expected.Skeleton.Names));
            Assert.That(actual.Skeleton.Parents, Is.EqualTo(expected.Skeleton.Parents));
            Assert.That(actual.Skeleton.Offsets, Is.EqualTo(expected.Skeleton.Offsets).Within(tolerance));
            for (int j = 0; j < expected.Skeleton.JointCount; j++)
            {
                Assert.That(actual.JointChannels[j], Is.EqualTo(expected.JointChannels[j]), $"channels of joint {j}");
                Assert.That(actual.EndSites[j].Length, Is.EqualTo(expected.EndSites[j].Length), $"End Sites of joint {j}");
            }

            Assert.That(actual.Motion.FrameCount, Is.EqualTo(expected.Motion.FrameCount));
            Assert.That(actual.Motion.FrameTime, Is.EqualTo(expected.Motion.FrameTime).Within(1e-6));
            Assert.That(actual.Motion.LocalPositions, Is.EqualTo(expected.Motion.LocalPositions).Within(tolerance));
            double[] a = actual.Motion.LocalRotations, b = expected.Motion.LocalRotations;
            for (int i = 0; i < a.Length; i += 4)
            {
                RotationAssert.SameRotation(QuaternionD.Read(a, i), QuaternionD.Read(b, i), tolerance, $"rotation {i / 4}");
            }
        }

        private static BvhAnimation WriteAndRead(BvhAnimation animation, string newLine)
        {
            var writer = new StringWriter();
            BvhWriter.Write(animation, writer, newLine);
            return BvhReader.Parse(writer.ToString(), "roundtrip.bvh");
        }

        [Test]
        public void RandomSkeletonsAndChannelOrdersSurviveWriteThenRead([Range(1, 25)] int seed)
        {
            BvhAnimation original = Generate(seed, 1 + seed % 9 + seed / 5, 7);
            BvhAnimation once = WriteAndRead(original, seed % 2 == 0 ? "\n" : "\r\n");
            AssertSameMotion(once, original, 1e-5);
            // Read → write → read: a file written by us reads back to the same values.
            BvhAnimation twice = WriteAndRead(once, "\n");
            AssertSameMotion(twice, once, 1e-5);
        }

        [Test]
        public void WriterRefusesJointsOutOfDepthFirstOrder()
        {
            // 0 → {1, 2}, 1 → 3: index order 0,1,2,3 is not depth-first (3 would be written before 2).
            var skeleton = new Skeleton(new[] { "a", "b", "c", "d" }, new[] { -1, 0, 0, 1 }, new double[12]);
            var motion = MotionClip.CreateRestPose(skeleton, 1, 0.1);
            var channels = new[] { new[] { BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation }, new[] { BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation }, new[] { BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation }, new[] { BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation } };
            var animation = new BvhAnimation(motion, channels, null, "x");
            Assert.That(() => BvhWriter.Write(animation, new StringWriter()), Throws.ArgumentException.With.Message.Contains("depth-first"));
        }

        [Test]
        public void LafanFileSurvivesReadWriteRead()
        {
            string dir = TestEnvironment.RequireLafan1();
            string path = Path.Combine(dir, "ground1_subject5.bvh");
            if (!File.Exists(path)) Assert.Ignore($"{path} not found; skipping.");
            BvhAnimation original = BvhReader.Read(path);
            Assert.That(original.Skeleton.JointCount, Is.EqualTo(22));
            Assert.That(original.ChannelCount, Is.EqualTo(69));
            BvhAnimation back = WriteAndRead(original, "\r\n");
            AssertSameMotion(back, original, 1e-5);
        }
    }
}
