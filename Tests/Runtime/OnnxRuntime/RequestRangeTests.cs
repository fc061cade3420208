using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Requests outside the trained ranges are warnings (they run); beyond the frame embeddings they are
    /// errors (refused before the network runs).
    /// </summary>
    [TestFixture]
    public sealed class RequestRangeTests
    {
        [Test]
        public void OutsideTheTrainedRangesRunsAndIsOnlyWarnedAbout()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            var report = new ModelCheckReport();
            ModelChecks.Request(model.Contract, 3, 60, report);
            Assert.That(report.HasErrors, Is.False);
            Assert.That(report.CountOf(CheckSeverity.Warning), Is.EqualTo(2), "P = 3 (trained 10) and n = 60 (trained 5..39)");

            var t = new Transition(model.Contract.Skeleton, 3, 60);
            for (int i = 0; i < t.KeyLocalRotations.Length; i += 4) t.KeyLocalRotations[i] = 1;
            model.Inbetween(t);
            foreach (double v in t.LocalRotations) Assert.That(double.IsFinite(v), Is.True);
        }

        [Test]
        public void BeyondTheFrameEmbeddingsIsRefused()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            var t = new Transition(model.Contract.Skeleton, 10, 246);
            var e = Assert.Throws<ArgumentException>(() => model.Inbetween(t))!;
            Assert.That(e.Message, Does.StartWith("P + n = 10 + 246 = 256 exceeds the model's largest frame index 255; expected"));
        }
    }
}
