using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using DeltaInterpolator.Cli.Baking;
using DeltaInterpolator.Cli.Scoring;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Issue 30: the humanoid rule (spine, neck and legs within 25° of the model's standing pose) and the up-axis
    /// checks refuse no file of the shipped data manifests with the manifests' own settings (reference frame,
    /// frame rate, map, up): a refusal there would stop both <c>prepare</c> (the training recipe, which retargets
    /// through the CLI) and <c>score</c>. The rig is built as <c>score</c> and <c>bake</c> build it (<see cref="MappedRig.Create"/>,
    /// through the manifest reader <c>score</c> uses); skips without ../shared/data.
    /// </summary>
    public sealed class ShippedManifestReferenceTests
    {
        [Test]
        public void NoFileOfAShippedManifestIsRefused()
        {
            string root = TestEnvironment.RepositoryRoot!;
            string datasets = Path.Combine(root, "Training", "Python~", "datasets");
            var manifests = new List<string>(Directory.GetFiles(datasets, "*.json"));
            manifests.Sort(System.StringComparer.Ordinal);
            Assert.That(manifests, Is.Not.Empty, datasets);
            ModelContract contract;
            using (Core.Inference.Inbetweener model = Tests.OnnxRuntime.TwoRigBakeTests.ShippedModel()) contract = model.Contract;
            var refused = new List<string>();
            int checkedFiles = 0, present = 0;
            var clock = Stopwatch.StartNew();
            foreach (string spec in manifests)
            {
                DataManifest manifest = DataManifest.Open(spec);
                if (!Directory.Exists(manifest.Folder)) continue;
                present++;
                foreach (DataManifest.Entry e in manifest.Entries(new string[0]))
                {
                    checkedFiles++;
                    try
                    {
                        BvhAnimation animation = BakeInput.WithFrameRate(BvhReader.Read(e.FilePath), e.Fps);
                        JointMap? map = BakeInput.LoadMap(e.Map, animation, contract);
                        MappedRig rig = MappedRig.Create(contract, animation.Motion, e.ReferenceFrame, e.FilePath, map, e.Up ?? UpAxis.Auto);
                        MotionClip motion = animation.Motion;
                        int first = System.Math.Min(e.FromFrame, motion.FrameCount - 2);
                        MotionClip excerpt = motion.Excerpt(first, System.Math.Min(600, motion.FrameCount - first));
                        rig.ToModel(excerpt, new[] { 0, excerpt.FrameCount - 1 });
                    }
                    catch (JointMapException x)
                    {
                        refused.Add(x.Message);
                    }
                    catch (System.ArgumentException x)
                    {
                        refused.Add(e.FilePath + ": " + x.Message);
                    }
                }
            }

            if (present == 0) Assert.Ignore("no shipped manifest's data folder is present (../shared/data absent); skipping.");
            TestContext.WriteLine($"{checkedFiles} files of {present} manifest(s) checked in {clock.Elapsed.TotalSeconds:0} s; {refused.Count} refused");
            foreach (string r in refused) TestContext.WriteLine(r);
            Assert.That(refused, Is.Empty);
        }
    }
}
