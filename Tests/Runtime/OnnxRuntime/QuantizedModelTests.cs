using System;
using System.IO;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The dynamic int8 copy of the tiny model (Tests/Fixtures~/tiny-model.int8*.onnx, written by
    /// <c>python3 -m deltainterp quantize --model Tests/Fixtures~/tiny-model.onnx --out
    /// Tests/Fixtures~/tiny-model.int8.onnx --min-weights 1</c>; com.microsoft DynamicQuantizeMatMul nodes) loads
    /// through the same ONNX Runtime path as a float export, with its lazy graphs found beside it, and the real
    /// ONNX Runtime kernels give network outputs close to the float model's on every golden request. The Python
    /// side checks the same files with its reference evaluator; this checks what the runtime computes.
    /// </summary>
    [TestFixture]
    public sealed class QuantizedModelTests
    {
        // max |int8 − float| / max |float| of a request's deltas; the tiny model measures about 1.5 %, a
        // wrong weight scale or a lost bias lands far above
        private const double RelativeTolerance = 0.03;

        private static string QuantizedModel => Path.Combine(Fixtures.Directory, "tiny-model.int8.onnx");

        public static System.Collections.Generic.IEnumerable<TestCaseData> Cases()
        {
            foreach (GoldenCase c in Fixtures.Golden) yield return new TestCaseData(c).SetName("Int8_" + c.Name);
        }

        [Test]
        public void LoadsWithItsLazyGraphsAndTheFloatContract()
        {
            using Inbetweener int8 = OnnxRuntimeInbetweener.Load(QuantizedModel, requireLazy: true);
            using Inbetweener float32 = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);
            Assert.That(int8.SupportsLazyDecoding, Is.True);
            Assert.That(int8.Contract.ToJson(), Is.EqualTo(float32.Contract.ToJson()), "the same contract as the float file");
        }

        [TestCaseSource(nameof(Cases))]
        public void NetworkOutputsStayCloseToFloat(GoldenCase c)
        {
            using Inbetweener float32 = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);
            using Inbetweener int8 = OnnxRuntimeInbetweener.Load(QuantizedModel, requireLazy: true);
            float32.Inbetween(c.ToTransition(float32.Contract.Skeleton));
            float[] rotationFloat = float32.LastRotation6DDelta.ToArray(), rootFloat = float32.LastRootPositionDelta.ToArray();
            int8.Inbetween(c.ToTransition(int8.Contract.Skeleton));
            double rotation = Relative(int8.LastRotation6DDelta, rotationFloat);
            double root = Relative(int8.LastRootPositionDelta, rootFloat);
            TestContext.Out.WriteLine($"{c.Name}: int8 vs float, max |diff| / max |float|: rotation_6d_delta {rotation:P2}, root_position_delta {root:P2}");
            Assert.That(rotation, Is.LessThan(RelativeTolerance), "rotation_6d_delta");
            Assert.That(root, Is.LessThan(RelativeTolerance), "root_position_delta");
            Assert.That(rotation + root, Is.GreaterThan(0), "the int8 file really differs from float (it is not a copy)");
        }

        private static double Relative(ReadOnlySpan<float> got, float[] want)
        {
            Assert.That(got.Length, Is.EqualTo(want.Length), "lengths");
            double worst = 0, peak = 0;
            for (int i = 0; i < want.Length; i++)
            {
                worst = Math.Max(worst, Math.Abs(got[i] - want[i]));
                peak = Math.Max(peak, Math.Abs(want[i]));
            }

            return worst / Math.Max(peak, 1e-12);
        }
    }
}
