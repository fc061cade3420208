using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Every backend builds its bindings through <see cref="BindingTargets.Fill"/>: each tensor is checked
    /// against the graph (ONNX Runtime's description of the tiny fixture model here) before it is attached,
    /// and a binding refused half-way is disposed, so no engine tensor or pinned array leaks.
    /// </summary>
    [TestFixture]
    public sealed class BindingTargetsTests
    {
        [Test]
        public void AttachesEveryTensorInOrderWhenTheGraphHasThemAll()
        {
            using OnnxRuntimeBackend backend = OnnxRuntimeBackend.Load(Fixtures.TinyModel);
            GraphTensors t = WholeGraphTensors();
            var target = new RecordingTarget();
            Assert.That(BindingTargets.Fill(target, backend.Description, t.Inputs, t.Outputs), Is.SameAs(target));
            var expected = new List<string>();
            foreach (InferenceTensor i in t.Inputs) expected.Add("in " + i.Name);
            foreach (InferenceTensor o in t.Outputs) expected.Add("out " + o.Name);
            Assert.That(target.Bound, Is.EqualTo(expected));
            Assert.That(target.Disposed, Is.False);
        }

        [Test]
        public void ATensorTheGraphLacksOrTypesOtherwiseIsRefusedByNameAndTheBindingDisposed()
        {
            using OnnxRuntimeBackend backend = OnnxRuntimeBackend.Load(Fixtures.TinyModel);
            GraphTensors t = WholeGraphTensors();
            var inputs = new List<InferenceTensor>(t.Inputs) { InferenceTensor.Float("no_such_input", 1) };
            var target = new RecordingTarget();
            var e = Assert.Throws<ModelContractException>(() => BindingTargets.Fill(target, backend.Description, inputs, t.Outputs));
            Assert.That(e!.Message, Does.Contain("no_such_input"));
            Assert.That(target.Disposed, Is.True);
            Assert.That(target.Bound, Has.Count.EqualTo(t.Inputs.Count), "the tensors before it were bound, the refused one was not");

            Assert.That(t.Inputs[0].Kind, Is.EqualTo(TensorElementKind.Float32), t.Inputs[0].Name);
            var wrongType = new List<InferenceTensor> { InferenceTensor.Int64(t.Inputs[0].Name, 1) };
            var second = new RecordingTarget();
            Assert.Throws<ModelContractException>(() => BindingTargets.Fill(second, backend.Description, wrongType, new InferenceTensor[0]));
            Assert.That(second.Disposed, Is.True);
        }

        private static GraphTensors WholeGraphTensors()
        {
            var report = new ModelCheckReport();
            ModelContract c = ModelContract.FromMetadata(Fixtures.TinyModel, OnnxMetadataReader.Read(Fixtures.TinyModel), report)!;
            report.ThrowIfErrors();
            return GraphTensors.Create(c, ModelGraphKind.Whole, 10, 30, 30);
        }

        private sealed class RecordingTarget : IBindingTarget
        {
            public List<string> Bound { get; } = new List<string>();

            public bool Disposed { get; private set; }

            public void BindInput(InferenceTensor tensor) => Bound.Add("in " + tensor.Name);

            public void BindOutput(InferenceTensor tensor) => Bound.Add("out " + tensor.Name);

            public void Dispose() => Disposed = true;
        }
    }
}
