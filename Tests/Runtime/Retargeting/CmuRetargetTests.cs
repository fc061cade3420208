using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>Real CMU files (../shared/data/cmu) onto the model's skeleton.</summary>
    public sealed class CmuRetargetTests
    {
        private static double LegLength(Skeleton s, string leg, string foot)
        {
            return Vector3D.Read(s.OffsetSpan, 3 * s.IndexOf(leg)).Length + Vector3D.Read(s.OffsetSpan, 3 * s.IndexOf(foot)).Length;
        }

        /// <summary>Median over frames (frame 0, the T-pose, excluded) of the lowest of the given joints' heights.</summary>
        private static double MedianLowestFoot(MotionClip clip, int firstFrame, params string[] feet)
        {
            double[] p = RetargetFixtures.GlobalPositions(clip);
            int j = clip.Skeleton.JointCount;
            var lowest = new List<double>();
            for (int f = firstFrame; f < clip.FrameCount; f++)
            {
                double low = double.MaxValue;
                foreach (string name in feet) low = Math.Min(low, p[(f * j + clip.Skeleton.IndexOf(name)) * 3 + 1]);
                lowest.Add(low);
            }

            lowest.Sort();
            int n = lowest.Count;
            return n % 2 == 1 ? lowest[n / 2] : 0.5 * (lowest[n / 2 - 1] + lowest[n / 2]);
        }

        [TestCase("02_04.bvh")]
        [TestCase("07_01.bvh")]
        [TestCase("09_12.bvh")]
        [TestCase("05_02.bvh")]
        public void FeetStayOnTheGround(string file)
        {
            string path = Path.Combine(RetargetFixtures.RequireCmu(), file);
            BvhAnimation cmu = BvhReader.Read(path);
            Skeleton model = RetargetFixtures.Lafan1();
            SkeletonMap map = SkeletonMap.Create(ReferencePose.FromFrame(cmu.Motion, 0), ReferencePose.ModelTPose(model), null, path);
            Assert.That(map.Map, Is.SameAs(JointMap.Cmu));
            MotionClip onModel = MotionResampler.Resample(map.ToTarget(cmu.Motion), 1.0 / 30.0);

            double before = MedianLowestFoot(cmu.Motion, 1, "LeftFoot", "RightFoot", "LeftToeBase", "RightToeBase") / LegLength(cmu.Skeleton, "LeftLeg", "LeftFoot");
            double after = MedianLowestFoot(onModel, 1, "LeftFoot", "RightFoot", "LeftToe", "RightToe") / LegLength(model, "LeftLeg", "LeftFoot");
            TestContext.WriteLine($"{file}: median lowest foot height ÷ leg length (thigh + shin) before {before:F4}, after {after:F4}, moved {Math.Abs(after - before):F4}; root scale {map.RootScale:F4}");
            Assert.That(Math.Abs(after - before), Is.LessThanOrEqualTo(0.03));
        }

        [Test]
        public void FeetStayOnTheGroundInTheDemoClip()
        {
            // The shipped demo clip (Samples~/Demo, no T-pose frame): its zero pose is the reference.
            string path = Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_01_01_jumps_turn.bvh");
            if (!File.Exists(path)) Assert.Ignore($"{path} absent (Samples~ not in this copy); skipping.");
            BvhAnimation cmu = BvhReader.Read(path);
            Skeleton model = RetargetFixtures.Lafan1();
            SkeletonMap map = SkeletonMap.Create(ReferencePose.Zero(cmu.Skeleton), ReferencePose.ModelTPose(model), null, path);
            MotionClip onModel = MotionResampler.Resample(map.ToTarget(cmu.Motion), 1.0 / 30.0);
            double before = MedianLowestFoot(cmu.Motion, 0, "LeftFoot", "RightFoot", "LeftToeBase", "RightToeBase") / LegLength(cmu.Skeleton, "LeftLeg", "LeftFoot");
            double after = MedianLowestFoot(onModel, 0, "LeftFoot", "RightFoot", "LeftToe", "RightToe") / LegLength(model, "LeftLeg", "LeftFoot");
            TestContext.WriteLine($"demo clip: median lowest foot height ÷ leg length (thigh + shin) before {before:F4}, after {after:F4}, moved {Math.Abs(after - before):F4}; root scale {map.RootScale:F4}");
            Assert.That(Math.Abs(after - before), Is.LessThanOrEqualTo(0.03));
        }

        [Test]
        public void CmuBonesPointLikeTheModelsOnEveryFrame()
        {
            string path = Path.Combine(RetargetFixtures.RequireCmu(), "02_04.bvh");
            BvhAnimation cmu = BvhReader.Read(path);
            Skeleton model = RetargetFixtures.Lafan1();
            SkeletonMap map = SkeletonMap.Create(ReferencePose.FromFrame(cmu.Motion, 0), ReferencePose.ModelTPose(model), null, path);
            MotionClip onModel = map.ToTarget(cmu.Motion);
            double[] ps = RetargetFixtures.GlobalPositions(cmu.Motion), pt = RetargetFixtures.GlobalPositions(onModel);
            int js = cmu.Skeleton.JointCount, jt = model.JointCount;
            double worst = 0;
            int bones = 0;
            for (int c = 1; c < jt; c++)
            {
                int p = model.Parents[c];
                if (!map.AlignedBones[p]) continue;
                bones++;
                int sc = JointMap.FindJoint(cmu.Skeleton, JointMap.Cmu.SourceChain(model.Names[c])![0]);
                for (int f = 0; f < cmu.Motion.FrameCount; f++)
                {
                    Vector3D a = Vector3D.Read(pt, (f * jt + c) * 3) - Vector3D.Read(pt, (f * jt + p) * 3);
                    Vector3D b = Vector3D.Read(ps, (f * js + sc) * 3) - Vector3D.Read(ps, (f * js + map.SourceJointOf(p)) * 3);
                    worst = Math.Max(worst, RetargetFixtures.Angle(a, b));
                }
            }

            TestContext.WriteLine($"02_04: {bones} aligned bones, largest world direction difference {worst:E2} rad over {cmu.Motion.FrameCount} frames");
            Assert.That(bones, Is.GreaterThanOrEqualTo(14));
            Assert.That(worst, Is.LessThan(1e-4));
        }
    }
}
