using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Retargeting
{
    /// <summary>
    /// Issue 30: the up-axis checks leave every real file alone. Every BVH under ../shared/data (LaFAN1, CMU in
    /// both conversions; all Y up) is read with <c>--up auto</c>'s rule and the CLI's default reference pose:
    /// none may be turned, none may come out lying down, and none may fail the humanoid rule of the CLI
    /// (spine, neck and legs within 25° of the model's standing pose). Skips without the data; at most
    /// <see cref="UpAxisDetection.MaxSampledFrames"/> frames of each file are judged and 600 retargeted.
    /// </summary>
    public sealed class SharedDataUpAxisTests
    {
        [Test]
        public void NoFileOfTheSharedDataIsTurnedOrRefused()
        {
            string? root = TestEnvironment.RepositoryRoot;
            string data = root == null ? "" : Path.GetFullPath(Path.Combine(root, "..", "shared", "data"));
            if (!Directory.Exists(data)) Assert.Ignore($"{data} absent; skipping the shared-data up-axis test.");
            var files = new List<string>(Directory.GetFiles(data, "*.bvh", SearchOption.AllDirectories));
            files.Sort(System.StringComparer.Ordinal);
            if (files.Count == 0) Assert.Ignore($"no .bvh under {data}; skipping.");
            Skeleton model = RetargetFixtures.Lafan1();
            var wrong = new List<string>();
            var clock = Stopwatch.StartNew();
            foreach (string file in files)
            {
                MotionClip motion = BvhReader.Read(file).Motion;
                JointMap map = JointMap.Detect(motion.Skeleton, model);
                ReferencePose reference = ReferencePose.Default(motion.Skeleton);
                UpAxisDecision up = UpAxisDecision.Decide(UpAxis.Auto, reference, false, motion, map);
                if (!up.IsIdentity)
                {
                    wrong.Add(file + ": " + up.Description);
                    continue;
                }

                try
                {
                    SkeletonMap toModel = SkeletonMap.Create(reference, ReferencePose.ModelTPose(model), map, file, null, up);
                    BoneDirections.RequireTPose(toModel, ReferencePose.ModelTPose(model), BoneDirections.DefaultMaxDegrees, file, BoneDirections.UprightBones);
                    MotionClip excerpt = motion.FrameCount > 600 ? motion.Excerpt(0, 600) : motion;
                    UpAxisDetection.RequireStanding(toModel.ToTarget(excerpt), file, up.Description);
                }
                catch (System.ArgumentException e)
                {
                    wrong.Add(e.Message);
                }
                catch (JointMapException e)
                {
                    wrong.Add(e.Message);
                }
            }

            TestContext.WriteLine($"{files.Count} files under {data} checked in {clock.Elapsed.TotalSeconds:0} s; {wrong.Count} turned or refused");
            foreach (string w in wrong) TestContext.WriteLine(w);
            Assert.That(wrong, Is.Empty);
        }
    }
}
