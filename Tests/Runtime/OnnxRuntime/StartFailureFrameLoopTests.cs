using System;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// A model whose load throws stops the character once, whatever the exception's type: the component's frame loop
    /// (<c>MotionInbetweener.Update</c>: <see cref="PlaybackStatus.ShouldStart"/>, then <see cref="PlaybackStatus.TryStart"/>
    /// around the load) over many frames, with the real ONNX Runtime backends of the tiny fixture behind a backend factory that
    /// throws a type of its own for one graph (as Sentis asserts or <c>new Worker</c> do). Before, the component caught only
    /// the package's own refusal types: any other left it waiting, and every frame loaded the graphs again.
    /// </summary>
    [TestFixture]
    public sealed class StartFailureFrameLoopTests
    {
        private const int Frames = 300;

        [Test]
        public void ABackendFactoryThrowingItsOwnTypeStopsTheCharacterOnceAndLoadsOnce()
        {
            var factory = new ThrowingFactory(ModelGraphKind.Keys, () => new EngineAssertionException("Assertion failure. Value was False"));
            var status = new PlaybackStatus();
            int escaped = RunFrames(status, factory);

            Assert.That(factory.Loads, Is.EqualTo(1), "one load over every frame: a failed load is not retried by the next frame");
            Assert.That(factory.OpenBackends, Is.EqualTo(0), "the whole graph opened before the failing one is disposed");
            Assert.That(escaped, Is.EqualTo(0), "the failure is the status', not an exception out of every frame");
            Assert.That(status.State, Is.EqualTo(PlaybackState.Failed));
            Assert.That(status.Reason, Does.Contain("'tiny-model'").And.Contain(nameof(EngineAssertionException)).And.Contain("Assertion failure").And.Contain("enable the component again"));
            Assert.That(status.Error, Is.InstanceOf<EngineAssertionException>());

            // Enabling the component again retries once.
            status.Wait("the component is enabled again");
            RunFrames(status, factory);
            Assert.That(factory.Loads, Is.EqualTo(2));
        }

        [Test]
        public void TheFactorysInvalidOperationExceptionKeepsItsOwnMessage()
        {
            var factory = new ThrowingFactory(ModelGraphKind.Whole, () => new InvalidOperationException("the graph asset is not a Sentis ModelAsset; reimport it"));
            var status = new PlaybackStatus();
            RunFrames(status, factory);
            Assert.That(factory.Loads, Is.EqualTo(1));
            Assert.That(status.Reason, Is.EqualTo("the graph asset is not a Sentis ModelAsset; reimport it"));
        }

        [Test]
        public void AFatalExceptionPropagatesOnceAndIsNotRetried()
        {
            var factory = new ThrowingFactory(ModelGraphKind.Whole, () => new OutOfMemoryException("no memory for the graph"));
            var status = new PlaybackStatus();
            int escaped = RunFrames(status, factory);
            Assert.That(escaped, Is.EqualTo(1), "the fatal exception reaches the engine's loop, once");
            Assert.That(factory.Loads, Is.EqualTo(1));
            Assert.That(status.State, Is.EqualTo(PlaybackState.Failed));
        }

        [Test]
        public void ALoadThatWorksRunsAndLoadsOnce()
        {
            var factory = new ThrowingFactory(null, () => new EngineAssertionException("never"));
            var status = new PlaybackStatus();
            RunFrames(status, factory);
            Assert.That(status.State, Is.EqualTo(PlaybackState.Running));
            Assert.That(factory.Loads, Is.EqualTo(1));
            Assert.That(factory.OpenBackends, Is.EqualTo(3), "the model stays loaded while it runs");
            factory.Model!.Dispose();
        }

        // The component's Update, frame after frame, with settings assigned: an exception out of it is what Unity logs before the
        // next frame, so the loop goes on as the engine's does.
        private static int RunFrames(PlaybackStatus status, ThrowingFactory factory)
        {
            int escaped = 0;
            for (int frame = 0; frame < Frames; frame++)
            {
                try
                {
                    if (status.ShouldStart(ready: true)) status.TryStart(() => factory.Model = InbetweenerLoader.Load(factory), "tiny-model");
                }
                catch (Exception)
                {
                    escaped++;
                }
            }

            return escaped;
        }

        /// <summary>An engine's own exception type, as Sentis' <c>UnityEngine.Assertions.AssertionException</c> is to this package.</summary>
        private sealed class EngineAssertionException : Exception
        {
            public EngineAssertionException(string message)
                : base(message)
            {
            }
        }

        /// <summary>The tiny fixture's real graphs on ONNX Runtime, except that opening <c>failing</c> throws; counts loads (whole graphs opened) and open backends.</summary>
        private sealed class ThrowingFactory : IModelGraphs
        {
            private readonly OnnxModelFiles _files = new OnnxModelFiles(Fixtures.TinyModel);
            private readonly ModelGraphKind? _failing;
            private readonly Func<Exception> _error;

            public ThrowingFactory(ModelGraphKind? failing, Func<Exception> error)
            {
                _failing = failing;
                _error = error;
            }

            public int Loads { get; private set; }

            public int OpenBackends { get; private set; }

            public Inbetweener? Model { get; set; }

            public string Source => "tiny-model";

            public bool HasLazyGraphs => _files.HasLazyGraphs;

            public IInferenceBackend Open(ModelGraphKind graph)
            {
                if (graph == ModelGraphKind.Whole) Loads++;
                if (graph == _failing) throw _error();
                return new Counted(_files.Open(graph), this);
            }

            private sealed class Counted : IInferenceBackend
            {
                private readonly IInferenceBackend _inner;
                private readonly ThrowingFactory _owner;
                private bool _disposed;

                public Counted(IInferenceBackend inner, ThrowingFactory owner)
                {
                    _inner = inner;
                    _owner = owner;
                    owner.OpenBackends++;
                }

                public ModelDescription Description => _inner.Description;

                public IInferenceBinding Bind(System.Collections.Generic.IReadOnlyList<InferenceTensor> inputs, System.Collections.Generic.IReadOnlyList<InferenceTensor> outputs) => _inner.Bind(inputs, outputs);

                public void Dispose()
                {
                    if (_disposed) return;
                    _disposed = true;
                    _owner.OpenBackends--;
                    _inner.Dispose();
                }
            }
        }
    }
}
