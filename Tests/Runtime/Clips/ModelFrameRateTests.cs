using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Clips;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    public class ModelFrameRateTests
    {
        [Test]
        public void TheTrainingRateComesFromTheContract()
        {
            Assert.That(ModelFrameRate.FromContractJson("{\"training\": {\"past_frames\": [10, 10], \"fps\": 24}}", "m.onnx"), Is.EqualTo(24));
        }

        [Test]
        public void WithoutARateThirtyIsAssumed()
        {
            Assert.That(ModelFrameRate.FromContractJson("{\"name\": \"x\"}", "m.onnx"), Is.EqualTo(ModelFrameRate.Default));
            Assert.That(ModelFrameRate.FromContractJson("{\"training\": {}}", "m.onnx"), Is.EqualTo(30));
        }

        [Test]
        public void ANonPositiveRateIsRefusedWithItsLine()
        {
            var e = Assert.Throws<DataFormatException>(() => ModelFrameRate.FromContractJson("{\"training\":\n {\"fps\": 0}}", "m.onnx"));
            Assert.That(e!.Message, Does.StartWith("m.onnx:2:"));
        }
    }
}
