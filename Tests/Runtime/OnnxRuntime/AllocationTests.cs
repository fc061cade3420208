using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>In steady state neither a whole transition nor a lazily decoded frame allocates managed memory.</summary>
    [TestFixture]
    public sealed class AllocationTests
    {
        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void SteadyStateTransitionsAllocateNothing()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);
            GoldenCase c = Fixtures.Golden[2];
            Transition t = c.ToTransition(model.Contract.Skeleton);
            var global = new double[c.MissingFrames * model.Contract.JointCount * 3];
            LazyInbetweener lazy = model.CreateLazy(c.PastFrames, c.MissingFrames);
            for (int i = 0; i < 3; i++)
            {
                model.Inbetween(t, global);
                lazy.Begin(t);
                lazy.DecodeFrame(i);
            }

            const int calls = 200;
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < calls; i++) model.Inbetween(t, global);
            long whole = GC.GetAllocatedBytesForCurrentThread() - before;

            before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < calls; i++)
            {
                lazy.Begin(t);
                lazy.DecodeFrame(i % c.MissingFrames);
            }

            long lazyBytes = GC.GetAllocatedBytesForCurrentThread() - before;
            TestContext.Out.WriteLine($"{calls} whole transitions (n = {c.MissingFrames}): {whole} bytes; {calls} lazy begin + frame: {lazyBytes} bytes");
            Assert.That(whole, Is.EqualTo(0), "bytes allocated by whole transitions");
            Assert.That(lazyBytes, Is.EqualTo(0), "bytes allocated by lazy decoding");
        }
    }
}
