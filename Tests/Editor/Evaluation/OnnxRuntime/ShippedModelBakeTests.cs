using System.IO;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.Evaluation.Benchmark;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Baking;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// <see cref="ClipBaker"/> with the shipped model: settings read from its contract, and baking a
    /// LaFAN1 subject-5 file with a key every 15 frames beats SLERP in L2Q and L2P against the file's own
    /// frames, keys kept exactly. Skips without the model or LaFAN1.
    /// </summary>
    [TestFixture]
    public sealed class ShippedModelBakeTests
    {
        [Test]
        public void SettingsComeFromTheContract()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(ShippedModelTests.RequireShippedModel());
            BakeSettings settings = BakeSettings.ForModel(model.Contract);
            Assert.That(settings.PastFrames, Is.EqualTo(model.Contract.TrainingPastFrames.Max));
            Assert.That(settings.MaxFrameIndex, Is.EqualTo(model.Contract.MaxFrameIndex));
            Assert.That(settings.TrainedMissingFrames, Is.EqualTo(model.Contract.TrainingMissingFrames));
            Assert.That(settings.ShortContext, Is.EqualTo(BakeSettings.ChooseShortContext(model.Contract.TrainingPastFrames)));
            Assert.That(BakeSettings.ForModel(model.Contract, ShortContextPolicy.FeedAvailable).ShortContext, Is.EqualTo(ShortContextPolicy.FeedAvailable));
        }

        [Test]
        public void EveryFifteenFramesOnObstacles1BeatsSlerp()
        {
            string path = ShippedModelTests.RequireShippedModel();
            string data = TestEnvironment.RequireLafan1();
            string file = Path.Combine(data, "obstacles1_subject5.bvh");
            string stats = Path.Combine(data, "train_stats_official.json");
            if (!File.Exists(file) || !File.Exists(stats)) Assert.Ignore($"{file} or {stats} not found; skipping.");
            BvhAnimation animation = BvhReader.Read(file);
            double[] std = BenchmarkStatistics.Load(stats).StandardDeviation;
            int[] keys = KeyFrames.Every(15, animation.Motion.FrameCount);

            using Inbetweener model = OnnxRuntimeInbetweener.Load(path);
            var modelBaker = new ClipBaker(model, BakeSettings.ForModel(model.Contract));
            var slerpBaker = new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline());
            var bakedModel = modelBaker.Bake(animation.Motion, modelBaker.Plan(animation.Motion.FrameCount, keys));
            var bakedSlerp = slerpBaker.Bake(animation.Motion, slerpBaker.Plan(animation.Motion.FrameCount, keys));
            BakeAccuracy m = BakeAccuracy.Measure(animation.Motion, bakedModel, keys, std);
            BakeAccuracy s = BakeAccuracy.Measure(animation.Motion, bakedSlerp, keys, std);
            TestContext.Out.WriteLine($"every 15 on obstacles1_subject5 ({m.Frames} frames): model L2Q {m.L2Q:F4} L2P {m.L2P:F4} pos {m.MeanPositionError:F3}; SLERP L2Q {s.L2Q:F4} L2P {s.L2P:F4} pos {s.MeanPositionError:F3}");
            Assert.That(m.L2Q, Is.LessThan(s.L2Q));
            Assert.That(m.L2P, Is.LessThan(s.L2P));
            foreach (int key in keys) ClipBakerTests.AssertSameFrame(bakedModel, key, animation.Motion, key);
        }
    }
}
