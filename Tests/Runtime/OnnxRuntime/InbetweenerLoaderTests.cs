using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// <see cref="InbetweenerLoader"/>, the one loader of every engine, on real ONNX Runtime sessions: lazy graphs
    /// both or neither, <see cref="LazyGraphs.Required"/> refused by name, and a graph that fails to open
    /// leaves no session behind (the ones opened before it are disposed).
    /// </summary>
    [TestFixture]
    public sealed class InbetweenerLoaderTests
    {
        private string _dir = null!;

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "deltainterp-loader-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void DeleteFolder()
        {
            if (Directory.Exists(_dir)) Directory.Delete(_dir, true);
        }

        private string Copy(params string[] graphs)
        {
            foreach (string g in graphs)
            {
                string name = g == "whole" ? "tiny-model.onnx" : "tiny-model." + g + ".onnx";
                File.Copy(Path.Combine(Fixtures.Directory, name), Path.Combine(_dir, name.Replace("tiny-model", "m")));
            }

            return Path.Combine(_dir, "m.onnx");
        }

        [Test]
        public void AllThreeGraphsLoadForLazyDecoding()
        {
            using Inbetweener model = InbetweenerLoader.Load(new OnnxModelFiles(Copy("whole", "keys", "frame")));
            Assert.That(model.KeysContract, Is.Not.Null);
            Assert.That(model.FrameContract, Is.Not.Null);
        }

        [Test]
        public void OneLazyGraphAloneLoadsTheWholeGraphOnly()
        {
            var files = new OnnxModelFiles(Copy("whole", "keys"));
            Assert.That(files.HasLazyGraphs, Is.False);
            using Inbetweener model = InbetweenerLoader.Load(files);
            Assert.That(model.KeysContract, Is.Null);
        }

        [Test]
        public void NoneLoadsTheWholeGraphEvenWhenTheLazyOnesAreThere()
        {
            var files = new Recording(new OnnxModelFiles(Copy("whole", "keys", "frame")));
            using Inbetweener model = InbetweenerLoader.Load(files, LazyGraphs.None);
            Assert.That(files.Opened, Is.EqualTo(new[] { ModelGraphKind.Whole }));
        }

        [Test]
        public void RequiredLazyGraphsAreRefusedByNameBeforeAnythingOpens()
        {
            var files = new Recording(new OnnxModelFiles(Copy("whole")));
            var e = Assert.Throws<ModelContractException>(() => InbetweenerLoader.Load(files, LazyGraphs.Required));
            Assert.That(e!.Message, Does.Contain("m.onnx"));
            Assert.That(e.Message, Does.Contain("NAME.keys.onnx"));
            Assert.That(files.Opened, Is.Empty);
        }

        [Test]
        public void AGraphThatFailsToOpenDisposesTheOnesOpenedBeforeIt()
        {
            string path = Copy("whole", "keys");
            File.WriteAllBytes(Path.Combine(_dir, "m.frame.onnx"), new byte[] { 1, 2, 3, 4, 5 }); // not a model
            var files = new Recording(new OnnxModelFiles(path));
            Assert.Throws<ModelContractException>(() => InbetweenerLoader.Load(files));
            Assert.That(files.Opened, Is.EqualTo(new[] { ModelGraphKind.Whole, ModelGraphKind.Keys, ModelGraphKind.Frame }));
            Assert.That(files.Backends.Count, Is.EqualTo(2));
            Assert.That(files.Backends.TrueForAll(b => b.Disposed), Is.True, "the whole and keys sessions must be released");
        }

        [Test]
        public void AModelWithoutTrainingFpsIsTakenAt30FpsOnceAndSaysSo()
        {
            string json = "{\"contract_version\": 2, \"graph\": \"whole\", \"skeleton\": {\"names\": [\"Hips\"], \"parents\": [-1], \"offsets\": [[0, 0, 0]]}, " +
                          "\"unit_scale\": 0.01, \"training\": {\"past_frames\": [10, 10], \"future_frames\": [1, 1], \"missing_frames\": [5, 39]}}";
            var report = new ModelCheckReport();
            ModelContract? contract = ModelContract.Parse(json, "old.onnx", report);
            Assert.That(contract, Is.Not.Null);
            Assert.That(contract!.FramesPerSecond, Is.EqualTo(30));
            Assert.That(contract.TrainingFps, Is.EqualTo(0));
            Assert.That(report, Has.Some.Matches<ModelCheck>(c => c.Severity == CheckSeverity.Info && c.Message.Contains("no training.fps")));

            var with24 = ModelContract.Parse(json.Replace("[5, 39]}", "[5, 39], \"fps\": 24}"), "m24.onnx", new ModelCheckReport());
            Assert.That(with24!.FramesPerSecond, Is.EqualTo(24));
        }

        /// <summary>The real file set, recording what was opened and whether each session was released.</summary>
        private sealed class Recording : IModelGraphs
        {
            private readonly OnnxModelFiles _files;

            public Recording(OnnxModelFiles files) => _files = files;

            public List<ModelGraphKind> Opened { get; } = new List<ModelGraphKind>();

            public List<Tracked> Backends { get; } = new List<Tracked>();

            public string Source => _files.Source;

            public bool HasLazyGraphs => _files.HasLazyGraphs;

            public IInferenceBackend Open(ModelGraphKind graph)
            {
                Opened.Add(graph);
                var b = new Tracked(_files.Open(graph));
                Backends.Add(b);
                return b;
            }
        }

        private sealed class Tracked : IInferenceBackend
        {
            private readonly IInferenceBackend _inner;

            public Tracked(IInferenceBackend inner) => _inner = inner;

            public bool Disposed { get; private set; }

            public ModelDescription Description => _inner.Description;

            public IInferenceBinding Bind(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs) => _inner.Bind(inputs, outputs);

            public void Dispose()
            {
                Disposed = true;
                _inner.Dispose();
            }
        }
    }
}
