using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;
using System.Threading.Tasks;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Loading a model runs it once (the probe of its constant outputs), so a graph outside the contract must be
    /// refused before that run: a valid-looking model with a 10^12-trip <c>Loop</c> is refused at once with a
    /// message naming the operator, instead of never returning. Every model this project ships passes.
    /// </summary>
    [TestFixture]
    public sealed class ProbeRunIsBoundedTests
    {
        [Test]
        public void ALoopOfATrillionTripsIsRefusedBeforeAnythingRuns()
        {
            string dir = Path.Combine(Path.GetTempPath(), "deltainterp-loop-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(dir);
            try
            {
                string path = HostileModels.WriteWithLoop(Path.Combine(dir, "loop.onnx"), 1_000_000_000_000L);
                // Bounded: before the refusal existed this load never returned.
                Task<Exception?> load = Task.Run(() =>
                {
                    try
                    {
                        OnnxRuntimeInbetweener.Load(path).Dispose();
                        return null;
                    }
                    catch (Exception e)
                    {
                        return e;
                    }
                });
                Assert.That(load.Wait(TimeSpan.FromSeconds(60)), Is.True, "loading a model with a huge Loop did not return within 60 s");
                Exception? error = load.Result;
                Assert.That(error, Is.InstanceOf<ModelContractException>(), "refused as outside the contract: " + error);
                Assert.That(error!.Message, Does.StartWith(path + ": "));
                Assert.That(error.Message, Does.Contain("operator Loop"));
                Assert.That(error.Message, Does.Contain("; expected"));
                Assert.That(error.Message, Does.Not.Contain("\n"));
            }
            finally
            {
                Directory.Delete(dir, true);
            }
        }

        [Test]
        public void ReadsTheOperatorsOfTheGraphWithoutAnEngine()
        {
            byte[] bytes = File.ReadAllBytes(HostileModels.WriteWithLoop(Path.Combine(Path.GetTempPath(), "deltainterp-ops-" + Guid.NewGuid().ToString("N").Substring(0, 8) + ".onnx"), 5));
            IReadOnlyList<string> ops = OnnxMetadataReader.ReadOperators(bytes, "loop.onnx");
            Assert.That(ops, Does.Contain("Loop").And.Contain("MatMul"));
            Assert.That(ops, Is.Ordered.Using((IComparer<string>)StringComparer.Ordinal));
            Assert.Throws<ModelContractException>(() => ModelOperators.Check(bytes, "loop.onnx", allowQuantized: true));
        }

        [TestCase("Tests/Fixtures~/tiny-model.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.keys.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.frame.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model-v1.onnx")]
        [TestCase("Runtime/Models/DeltaInterpolator-CMU.onnx")]
        [TestCase("Runtime/Models/DeltaInterpolator-CMU.keys.onnx")]
        [TestCase("Runtime/Models/DeltaInterpolator-CMU.frame.onnx")]
        [TestCase("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx")]
        public void EveryShippedModelLiesInsideThePortableOperators(string relative)
        {
            string path = Inference.ModelContractJsonTests.Repository(relative);
            Assert.DoesNotThrow(() => ModelOperators.Check(File.ReadAllBytes(path), path, allowQuantized: false));
        }

        [TestCase("Tests/Fixtures~/tiny-model.int8.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.int8.keys.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.int8.frame.onnx")]
        public void QuantizedModelsLoadOnOnnxRuntimeOnly(string relative)
        {
            string path = Inference.ModelContractJsonTests.Repository(relative);
            byte[] bytes = File.ReadAllBytes(path);
            Assert.DoesNotThrow(() => ModelOperators.Check(bytes, path, allowQuantized: true));
            Assert.Throws<ModelContractException>(() => ModelOperators.Check(bytes, path, allowQuantized: false), "Sentis imports no quantized operator");
        }

        [Test]
        public void TheListsAreThePythonTrainersLists()
        {
            string? operators = null;
            for (string? dir = AppContext.BaseDirectory; dir != null && operators == null; dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar)))
            {
                string candidate = Path.Combine(dir, "Training", "Python~", "deltainterp", "operators.py");
                if (File.Exists(candidate)) operators = candidate;
            }

            if (operators == null) Assert.Ignore("Training/Python~/deltainterp/operators.py not found (package installed without Training/)");
            string text = File.ReadAllText(operators!);
            Match allowed = Regex.Match(text, @"^ALLOWED[^=]*=\s*\{(.*?)^\}", RegexOptions.Multiline | RegexOptions.Singleline);
            Match forbidden = Regex.Match(text, @"^FORBIDDEN[^=]*=\s*\{(.*?)^\}", RegexOptions.Multiline | RegexOptions.Singleline);
            Assert.That(allowed.Success && forbidden.Success, Is.True, "ALLOWED and FORBIDDEN in operators.py");
            var python = new List<string>();
            foreach (Match m in Regex.Matches(Regex.Replace(allowed.Groups[1].Value, "#[^\n]*", ""), "\"([A-Za-z]+)\"")) python.Add(m.Groups[1].Value);
            var pythonForbidden = new List<string>();
            foreach (Match m in Regex.Matches(forbidden.Groups[1].Value, "^\\s*\"([A-Za-z]+)\":", RegexOptions.Multiline)) pythonForbidden.Add(m.Groups[1].Value);
            Assert.That(ModelOperators.Portable, Is.EquivalentTo(python));
            Assert.That(ModelOperators.Forbidden.Keys, Is.EquivalentTo(pythonForbidden));
        }
    }

    /// <summary>
    /// Models outside the contract, built from the tiny fixture: its bytes with a second <c>graph</c> field appended,
    /// which protobuf merges into the first (a repeated message field's rule), so the metadata stays valid and the
    /// graph gains a node.
    /// </summary>
    public static class HostileModels
    {
        /// <summary>
        /// Writes the tiny fixture plus a <c>Loop</c> of <paramref name="trips"/> trips (an Identity body carrying one
        /// float) to <paramref name="path"/> and returns it.
        /// </summary>
        public static string WriteWithLoop(string path, long trips)
        {
            byte[] tiny = File.ReadAllBytes(Fixtures.TinyModel);
            var body = new Proto()
                .Message(1, new Proto().Text(1, "di_cond").Text(2, "di_cond_out").Text(4, "Identity").Bytes())
                .Message(1, new Proto().Text(1, "di_v").Text(2, "di_v_out").Text(4, "Identity").Bytes())
                .Text(2, "di_body")
                .Message(11, Scalar("di_iter", 7)).Message(11, Scalar("di_cond", 9)).Message(11, Scalar("di_v", 1))
                .Message(12, Scalar("di_cond_out", 9)).Message(12, Scalar("di_v_out", 1));
            var loop = new Proto()
                .Text(1, "di_trips").Text(1, "").Text(1, "di_v0").Text(2, "di_v_end").Text(3, "di_huge_loop").Text(4, "Loop")
                .Message(5, new Proto().Text(1, "body").Message(6, body.Bytes()).Varint(20, 5).Bytes());
            var graph = new Proto()
                .Message(1, loop.Bytes())
                .Message(5, new Proto().Varint(2, 7).Message(7, new Proto().RawVarint(trips).Bytes()).Text(8, "di_trips").Bytes())
                .Message(5, new Proto().Varint(2, 1).Message(4, BitConverter.GetBytes(0f)).Text(8, "di_v0").Bytes());
            byte[] extra = new Proto().Message(7, graph.Bytes()).Bytes();
            var all = new byte[tiny.Length + extra.Length];
            tiny.CopyTo(all, 0);
            extra.CopyTo(all, tiny.Length);
            File.WriteAllBytes(path, all);
            return path;
        }

        // A ValueInfoProto: name, and a scalar tensor type of an ONNX element type (1 float, 7 int64, 9 bool).
        private static byte[] Scalar(string name, int elementType) => new Proto()
            .Text(1, name)
            .Message(2, new Proto().Message(1, new Proto().Varint(1, elementType).Message(2, Array.Empty<byte>()).Bytes()).Bytes())
            .Bytes();

        /// <summary>The protobuf wire format, enough to write the few messages above.</summary>
        private sealed class Proto
        {
            private readonly MemoryStream _bytes = new MemoryStream();

            public Proto Varint(int field, long value) => Tag(field, 0).RawVarint(value);

            public Proto Text(int field, string text) => Message(field, Encoding.UTF8.GetBytes(text));

            public Proto Message(int field, byte[] bytes)
            {
                Tag(field, 2).RawVarint(bytes.Length);
                _bytes.Write(bytes, 0, bytes.Length);
                return this;
            }

            public Proto RawVarint(long value)
            {
                ulong v = (ulong)value;
                while (v >= 0x80)
                {
                    _bytes.WriteByte((byte)(v | 0x80));
                    v >>= 7;
                }

                _bytes.WriteByte((byte)v);
                return this;
            }

            public byte[] Bytes() => _bytes.ToArray();

            private Proto Tag(int field, int wire) => RawVarint(((long)field << 3) | (long)wire);
        }
    }
}
