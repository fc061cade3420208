using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Inference;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Inference
{
    public class ModelMetadataTextTests
    {
        [Test]
        public void MetadataSurvivesTheTripThroughText()
        {
            // The contract itself is JSON: quotes, backslashes, newlines and non-ASCII must come back as they were.
            var metadata = new Dictionary<string, string>
            {
                ["deltainterp"] = "{\"name\": \"Δ-Interp\", \"skeleton\": {\"names\": [\"Hips\", \"Spine\"]},\n \"path\": \"C:\\\\x\"\t}",
                ["contract_version"] = "1",
                ["empty"] = "",
                ["control"] = "a\u0001b",
            };

            string text = ModelMetadataText.Write(metadata);
            Dictionary<string, string> back = ModelMetadataText.Read(text, "model.onnx");

            Assert.That(back, Is.EquivalentTo(metadata));
            Assert.That(ModelMetadataText.Write(back), Is.EqualTo(text));
        }

        [Test]
        public void KeysAreWrittenInOrdinalOrder()
        {
            string text = ModelMetadataText.Write(new Dictionary<string, string> { ["b"] = "2", ["a"] = "1" });

            Assert.That(text, Is.EqualTo("{\"a\": \"1\", \"b\": \"2\"}"));
        }

        [Test]
        public void ANonStringValueIsRefused()
        {
            Assert.That(() => ModelMetadataText.Read("{\"contract_version\": 1}", "asset"), Throws.InstanceOf<DataFormatException>());
        }
    }
}
