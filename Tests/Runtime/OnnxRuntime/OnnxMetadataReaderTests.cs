using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Tests.Inference;
using Microsoft.ML.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Core's protobuf reader of <c>metadata_props</c> gives what ONNX Runtime reports for the same files,
    /// and refuses truncated or garbage bytes with a one-line message (never another exception).
    /// </summary>
    [TestFixture]
    public sealed class OnnxMetadataReaderTests
    {
        [TestCase("Tests/Fixtures~/tiny-model.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.keys.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.frame.onnx")]
        [TestCase("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx")]
        [TestCase("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.keys.onnx")]
        [TestCase("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.frame.onnx")]
        public void ReadsWhatOnnxRuntimeReports(string relative)
        {
            string path = ModelContractJsonTests.Repository(relative);
            IReadOnlyDictionary<string, string> ours = OnnxMetadataReader.Read(path);
            Dictionary<string, string> theirs;
            using (var session = new InferenceSession(path))
            {
                theirs = new Dictionary<string, string>(session.ModelMetadata.CustomMetadataMap);
            }

            Assert.That(theirs.Count, Is.EqualTo(2), "contract_version and deltainterp");
            Assert.That(ours, Is.EquivalentTo(theirs));
        }

        [Test]
        public void EveryTruncationIsRefusedOrKeepsOnlyCompleteEntries()
        {
            byte[] bytes = File.ReadAllBytes(Fixtures.TinyModel);
            IReadOnlyDictionary<string, string> full = OnnxMetadataReader.Read(bytes, "tiny");
            int refused = 0, read = 0;
            // Every length near the metadata (the file's tail) and a stride through the rest.
            int tail = Math.Max(0, bytes.Length - 8192);
            for (int length = 0; length < bytes.Length; length += length < tail ? 97 : 1)
            {
                try
                {
                    IReadOnlyDictionary<string, string> part = OnnxMetadataReader.Read(bytes.AsSpan(0, length), "cut.onnx");
                    read++;
                    foreach (KeyValuePair<string, string> kv in part) Assert.That(full[kv.Key], Is.EqualTo(kv.Value), $"length {length}");
                }
                catch (ModelContractException e)
                {
                    refused++;
                    Assert.That(e.Message, Does.StartWith("cut.onnx: "));
                    Assert.That(e.Message, Does.Contain("; expected"));
                }
            }

            TestContext.Out.WriteLine($"{bytes.Length} bytes: {refused} truncations refused, {read} read as a shorter model");
            Assert.That(refused, Is.GreaterThan(0));
        }

        [Test]
        public void GarbageIsRefusedWithOneLine()
        {
            var random = new Random(7);
            int refused = 0;
            for (int i = 0; i < 2000; i++)
            {
                var bytes = new byte[1 + random.Next(512)];
                random.NextBytes(bytes);
                try
                {
                    OnnxMetadataReader.Read(bytes, "noise.onnx");
                }
                catch (ModelContractException e)
                {
                    refused++;
                    Assert.That(e.Message, Does.StartWith("noise.onnx: "));
                    Assert.That(e.Message, Does.Not.Contain("\n"));
                }
            }

            Assert.That(refused, Is.EqualTo(2000));
        }

        [TestCase(new byte[0], "the file holds no ONNX graph")]
        [TestCase(new byte[] { 0x08 }, "ends inside a varint")]
        [TestCase(new byte[] { 0x72, 0x05, 0x0a }, "claims 5 bytes but 1 remain")]
        [TestCase(new byte[] { 0x08, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0x01 }, "longer than 10 bytes")]
        [TestCase(new byte[] { 0x0e }, "wire type 6")]
        [TestCase(new byte[] { 0x00 }, "field number 0")]
        [TestCase(new byte[] { 0x0b, 0x10, 0x01 }, "group 1 is never closed")]
        [TestCase(new byte[] { 0x0b, 0x14 }, "group 1 is closed as 2")]
        [TestCase(new byte[] { 0x72, 0x03, 0x0a, 0x01, 0xff, 0x3a, 0x00 }, "not valid UTF-8")]
        public void MalformedBytesAreNamed(byte[] bytes, string what)
        {
            var e = Assert.Throws<ModelContractException>(() => OnnxMetadataReader.Read(bytes, "bad.onnx"))!;
            Assert.That(e.Message, Does.StartWith("bad.onnx: "));
            Assert.That(e.Message, Does.Contain(what));
        }

        [Test]
        public void UnknownFieldsOfEveryWireTypeAndGroupsAreSkipped()
        {
            var bytes = new List<byte>
            {
                0x08, 0x07,                               // ir_version = 7 (varint)
                0x19, 1, 2, 3, 4, 5, 6, 7, 8,             // field 3, fixed64
                0x25, 1, 2, 3, 4,                         // field 4, fixed32
                0x2b, 0x08, 0x01, 0x33, 0x34, 0x2c,       // field 5 group holding a varint and an empty nested group 6
                0x3a, 0x00,                               // graph (field 7), empty
                0x72, 0x0a, 0x0a, 0x01, (byte)'k', 0x12, 0x01, (byte)'v', 0x18, 0x05, 0x22, 0x00, // entry k=v plus unknown fields 3 and 4
                0x72, 0x03, 0x0a, 0x01, (byte)'e',        // entry e with no value
            };
            IReadOnlyDictionary<string, string> m = OnnxMetadataReader.Read(bytes.ToArray(), "hand.onnx");
            Assert.That(m, Is.EquivalentTo(new Dictionary<string, string> { ["k"] = "v", ["e"] = "" }));
        }
    }
}
