using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The one builder of graph tensors: names, shapes and integer inputs as the Python exporter feeds
    /// them (golden.json), the graphs' own inputs, and the key memory shared between the lazy graphs.
    /// </summary>
    [TestFixture]
    public sealed class GraphTensorsTests
    {
        private static ModelContract Contract(string path)
        {
            var report = new ModelCheckReport();
            ModelContract c = ModelContract.FromMetadata(path, OnnxMetadataReader.Read(path), report)!;
            report.ThrowIfErrors();
            return c;
        }

        [Test]
        public void IntegerInputsEqualThePythonPipelines()
        {
            ModelContract c = Contract(Fixtures.TinyModel);
            foreach (GoldenCase g in Fixtures.Golden)
            {
                GraphTensors t = GraphTensors.Create(c, ModelGraphKind.Whole, g.PastFrames, g.MissingFrames, g.MissingFrames);
                Assert.That(Array.ConvertAll(t.KeyFrameIndices!.Longs!, v => (double)v), Is.EqualTo(g.KeyFrameIndices), g.Name);
                Assert.That(Array.ConvertAll(t.QueryFrameIndices!.Longs!, v => (double)v), Is.EqualTo(g.QueryFrameIndices), g.Name);
                Assert.That(Array.ConvertAll(t.GapLength.Longs!, v => (double)v), Is.EqualTo(g.GapLength), g.Name);
                Assert.That(t.KeyFeatures!.Length, Is.EqualTo(g.KeyFeatures.Length), g.Name);
            }
        }

        [TestCase("tiny-model.onnx", ModelGraphKind.Whole)]
        [TestCase("tiny-model.keys.onnx", ModelGraphKind.Keys)]
        [TestCase("tiny-model.frame.onnx", ModelGraphKind.Frame)]
        public void InputsAreExactlyTheGraphsInputsWithItsElementTypes(string file, ModelGraphKind kind)
        {
            string path = System.IO.Path.Combine(Fixtures.Directory, file);
            ModelContract c = Contract(path);
            GraphTensors keys = GraphTensors.Create(c, ModelGraphKind.Keys, 10, 30, 0, constants: true);
            GraphTensors t = kind == ModelGraphKind.Whole ? GraphTensors.Create(c, kind, 10, 30, 30, constants: true)
                : kind == ModelGraphKind.Keys ? keys : GraphTensors.ForFrame(c, keys, 1, constants: true);
            using OnnxRuntimeBackend backend = OnnxRuntimeBackend.Load(path);
            var names = new List<string>();
            foreach (InferenceTensor i in t.Inputs)
            {
                names.Add(i.Name);
                TensorDescription d = backend.Description.FindInput(i.Name)!;
                Assert.That(d, Is.Not.Null, i.Name);
                Assert.That(i.Kind, Is.EqualTo(d.Kind), i.Name);
                Assert.That(i.Shape.Length, Is.EqualTo(d.Shape.Count), i.Name);
                for (int a = 0; a < d.Shape.Count; a++)
                {
                    if (d.Shape[a] >= 0) Assert.That(i.Shape[a], Is.EqualTo(d.Shape[a]), $"{i.Name} axis {a}");
                }
            }

            var graphInputs = new List<string>();
            foreach (TensorDescription d in backend.Description.Inputs) graphInputs.Add(d.Name);
            Assert.That(names, Is.EquivalentTo(graphInputs));
            // Runs as built, and the outputs have the shapes the graph produces.
            using IInferenceBinding binding = t.Bind(backend);
            Assert.DoesNotThrow(binding.Run);
            Assert.That(t.JointCount!.Longs![0], Is.EqualTo(22));
        }

        [Test]
        public void TheFrameGraphReadsTheKeysGraphsMemoryWithoutACopy()
        {
            ModelContract c = Contract(Fixtures.TinyModel);
            GraphTensors keys = GraphTensors.Create(c, ModelGraphKind.Keys, 4, 12, 0);
            GraphTensors frame = GraphTensors.ForFrame(c, keys, 1);
            Assert.That(frame.KeyMemory, Is.SameAs(keys.KeyMemory));
            Assert.That(frame.GapLength, Is.SameAs(keys.GapLength));
            // Contract version 2: a batch axis first (one row here).
            Assert.That(keys.KeyMemory!.Shape, Is.EqualTo(new long[] { 1, c.Architecture.Blocks, 2, 5, c.Architecture.Width }));
            Assert.That(frame.QueryFrameIndices!.Shape, Is.EqualTo(new long[] { 1, 1 }));
            frame.SetQuery(11);
            Assert.That(frame.QueryFrameIndices!.Longs, Is.EqualTo(new long[] { 4 + 11 }));
            Assert.Throws<ArgumentOutOfRangeException>(() => frame.SetQuery(12));
            Assert.Throws<ArgumentException>(() => GraphTensors.Create(c, ModelGraphKind.Frame, 4, 12, 1));
        }
    }
}
