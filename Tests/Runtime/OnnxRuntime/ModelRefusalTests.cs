using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Models that do not fit the contract are refused at load time (or at the first request, for a
    /// skeleton mismatch) with a one-line message naming the file and the mismatch. The broken models
    /// are the tiny fixture with same-length byte edits (protobuf strings keep their length prefixes, so
    /// the file stays a valid ONNX model that ONNX Runtime loads).
    /// </summary>
    [TestFixture]
    public sealed class ModelRefusalTests
    {
        private string _dir = null!;

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "deltainterp-refusal-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void DeleteFolder()
        {
            if (Directory.Exists(_dir)) Directory.Delete(_dir, true);
        }

        [Test]
        public void TheUnmodifiedFixtureLoads()
        {
            string path = Patched("ok.onnx");
            using Inbetweener model = OnnxRuntimeInbetweener.Load(path);
            Assert.That(model.Contract.ContractVersion, Is.EqualTo(ModelContract.Version));
        }

        [Test]
        public void OtherContractVersionIsRefused()
        {
            string path = Patched("v4.onnx", ("contract_version\u0012\u00013", "contract_version\u0012\u00014"), ("\"contract_version\": 3", "\"contract_version\": 4"));
            string message = Refusal(path);
            Assert.That(message, Does.Contain("contract version 4"));
            Assert.That(message, Does.Contain("expected a version from 1 to 3"));
        }

        [Test]
        public void MissingMetadataIsRefused()
        {
            string path = Patched("nometa.onnx", ("\u000bdeltainterp\u0012", "\u000bdeltainterq\u0012"));
            string message = Refusal(path);
            Assert.That(message, Does.Contain("no 'deltainterp' metadata"));
            Assert.That(message, Does.Contain("python3 -m deltainterp export"));
        }

        [Test]
        public void WrongInputNameIsRefused()
        {
            string path = Patched("renamed.onnx", ("key_features", "key_featurex"));
            string message = Refusal(path);
            Assert.That(message, Does.Contain("no input 'key_features'"));
            Assert.That(message, Does.Contain("key_featurex"));
        }

        [Test]
        public void NotAnOnnxFileIsRefused()
        {
            string path = Path.Combine(_dir, "text.onnx");
            File.WriteAllText(path, "HIERARCHY\nROOT Hips\n");
            string message = Refusal(path);
            // Core reads the graph's operators from the bytes before ONNX Runtime sees them (ModelOperators), so its
            // protobuf reader is the first to say that this is no ONNX file.
            Assert.That(message, Does.Contain("not a well-formed ONNX file"));
        }

        [Test]
        public void MissingFileIsRefused()
        {
            string message = Refusal(Path.Combine(_dir, "absent.onnx"));
            Assert.That(message, Does.Contain("does not exist"));
        }

        [Test]
        public void LazyGraphInPlaceOfTheWholeGraphIsRefused()
        {
            string path = Path.Combine(_dir, "keys-as-whole.onnx");
            File.Copy(Path.Combine(Fixtures.Directory, "tiny-model.keys.onnx"), path);
            string message = Refusal(path);
            Assert.That(message, Does.Contain("holds the 'keys' graph"));
        }

        [Test]
        public void OtherJointNamesInTheModelAreRefused()
        {
            // The model's metadata says "LeftTip" where the request skeleton (LaFAN1) has "LeftToe".
            string path = Patched("joints.onnx", ("\"LeftToe\"", "\"LeftTip\""));
            using Inbetweener lafan = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            Skeleton skeleton = lafan.Contract.Skeleton;
            using Inbetweener model = OnnxRuntimeInbetweener.Load(path);
            var e = Assert.Throws<ModelContractException>(() => model.Inbetween(new Transition(skeleton, 10, 5)))!;
            OneLine(e.Message, path);
            Assert.That(e.Message, Does.Contain("joint 4 is 'LeftTip' in the model but 'LeftToe'"));
        }

        [Test]
        public void OtherJointCountIsRefused()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            Skeleton full = model.Contract.Skeleton;
            var names = new string[full.JointCount - 1];
            var parents = new int[names.Length];
            var offsets = new double[3 * names.Length];
            for (int j = 0; j < names.Length; j++)
            {
                names[j] = full.Names[j];
                parents[j] = full.Parents[j];
            }

            var e = Assert.Throws<ModelContractException>(() => model.Inbetween(new Transition(new Skeleton(names, parents, offsets), 10, 5)))!;
            OneLine(e.Message, Fixtures.TinyModel);
            Assert.That(e.Message, Does.Contain("the model has 22 joints but the transition's skeleton has 21"));
        }

        [Test]
        public void TheContactFixtureLoadsWithItsContacts()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Path.Combine(Fixtures.Directory, "tiny-model-contacts.onnx"), requireLazy: true);
            Assert.That(model.Contract.HasFootContacts, Is.True);
            Assert.That(model.Contract.ContactJoints, Is.EqualTo(new[] { "LeftFoot", "LeftToe", "RightFoot", "RightToe" }));
            Assert.That(model.Contract.ContactThreshold, Is.EqualTo(0.4));
        }

        [Test]
        public void ContactOutputOfTheWrongShapeIsRefused()
        {
            // The head's Sigmoid becomes a Flatten (same length): foot_contacts comes out [B, N·4], not [B, N, 4].
            string path = PatchedContacts("flat.onnx", ("Sigmoid", "Flatten"));
            string message = Refusal(path);
            Assert.That(message, Does.Contain("foot_contacts"));
        }

        [Test]
        public void MissingContactOutputIsRefused()
        {
            // Renamed everywhere in the graph (it still runs), so the metadata's contact joints have no output.
            string path = PatchedContacts("renamed.onnx", ("foot_contacts", "foot_contactz"));
            string message = Refusal(path);
            Assert.That(message, Does.Contain("the metadata names contact_joints but the whole graph has no output 'foot_contacts'"));
        }

        [Test]
        public void ContactOutputWithoutContactJointsIsRefused()
        {
            string path = PatchedContacts("unnamed.onnx", ("\"contact_joints\"", "\"contact_jointz\""), ("\"contact_threshold\"", "\"contact_thresholx\""));
            string message = Refusal(path);
            Assert.That(message, Does.Contain("has a 'foot_contacts' output but its metadata names no contact_joints"));
        }

        [TestCase("\"contact_threshold\": 0.4", "\"contact_threshold\": 1.4", "metadata contact_threshold is 1.4")]
        [TestCase("\"contact_threshold\": 0.4", "\"contact_threshold\": 0.0", "metadata contact_threshold is 0")]
        [TestCase("\"LeftToe\", \"RightFoot\"", "\"LeftToe\", \"RightHand\"", "contact_joints[2] is 'RightHand' but the foot locker's channel 2 is 'RightFoot'")]
        [TestCase("\"LeftToe\", \"RightFoot\"", "\"LeftToe\",  \"LeftFoot\"", "contact_joints names 'LeftFoot' twice")]
        [TestCase("\"LeftToe\", \"RightFoot\"", "\"LeftToe\", \"RightFooX\"", "contact_joints[2] is 'RightFooX', not a joint of the model's skeleton")]
        public void BadContactMetadataIsRefused(string from, string to, string expected)
        {
            string path = PatchedContacts("meta.onnx", (from, to));
            string message = Refusal(path);
            Assert.That(message, Does.Contain(expected));
        }

        [Test]
        public void ContactProbabilitiesThatAreNotFiniteAreRefused()
        {
            // The real graph runs; the engine's foot_contacts come back NaN (a broken head or engine), which the probe refuses.
            string path = PatchedContacts("nan.onnx");
            var e = Assert.Throws<ModelContractException>(() => new Inbetweener(new NaNContacts(OnnxRuntimeBackend.Load(path))).Dispose())!;
            OneLine(e.Message, path);
            Assert.That(e.Message, Does.Contain("foot_contacts output holds NaN"));
        }

        [Test]
        public void TheVersion2FixtureLoadsWithoutContacts()
        {
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Path.Combine(Fixtures.Directory, "tiny-model-v2.onnx"), requireLazy: true);
            Assert.That(model.Contract.ContractVersion, Is.EqualTo(2));
            Assert.That(model.Contract.HasFootContacts, Is.False);
        }

        /// <summary>A real backend whose <c>foot_contacts</c> output is overwritten with NaN after every run.</summary>
        private sealed class NaNContacts : IInferenceBackend
        {
            private readonly IInferenceBackend _inner;

            public NaNContacts(IInferenceBackend inner) => _inner = inner;

            public ModelDescription Description => _inner.Description;

            public IInferenceBinding Bind(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs) => new Binding(_inner.Bind(inputs, outputs), outputs);

            public void Dispose() => _inner.Dispose();

            private sealed class Binding : IInferenceBinding
            {
                private readonly IInferenceBinding _inner;
                private readonly IReadOnlyList<InferenceTensor> _outputs;

                public Binding(IInferenceBinding inner, IReadOnlyList<InferenceTensor> outputs)
                {
                    _inner = inner;
                    _outputs = outputs;
                }

                public void Run()
                {
                    _inner.Run();
                    foreach (InferenceTensor t in _outputs)
                    {
                        if (t.Name == TensorNames.FootContacts) t.Floats![1] = float.NaN;
                    }
                }

                public void Dispose() => _inner.Dispose();
            }
        }

        /// <summary>A copy of the contact fixture (whole graph only) with same-length replacements.</summary>
        private string PatchedContacts(string name, params (string From, string To)[] edits) => Patched(Path.Combine(Fixtures.Directory, "tiny-model-contacts.onnx"), name, edits);

        private string Refusal(string path)
        {
            var e = Assert.Throws<ModelContractException>(() => OnnxRuntimeInbetweener.Load(path).Dispose())!;
            OneLine(e.Message, path);
            return e.Message;
        }

        private static void OneLine(string message, string path)
        {
            TestContext.Out.WriteLine(message);
            Assert.That(message, Does.StartWith(path + ": "));
            Assert.That(message, Does.Contain("; expected"));
            Assert.That(message, Does.Not.Contain("\n"));
        }

        /// <summary>One byte per char (the edits are ASCII and control bytes; Encoding.Latin1 is not in .NET Standard 2.1).</summary>
        private static byte[] Bytes(string s)
        {
            var b = new byte[s.Length];
            for (int i = 0; i < s.Length; i++) b[i] = checked((byte)s[i]);
            return b;
        }

        /// <summary>A copy of the tiny fixture with same-length replacements (each must occur).</summary>
        private string Patched(string name, params (string From, string To)[] edits) => Patched(Fixtures.TinyModel, name, edits);

        private string Patched(string source, string name, params (string From, string To)[] edits)
        {
            byte[] bytes = File.ReadAllBytes(source);
            foreach ((string from, string to) in edits)
            {
                byte[] f = Bytes(from), t = Bytes(to);
                Assert.That(t.Length, Is.EqualTo(f.Length), "edits must keep the length");
                int count = 0;
                for (int i = 0; i + f.Length <= bytes.Length; i++)
                {
                    if (bytes.AsSpan(i, f.Length).SequenceEqual(f))
                    {
                        t.CopyTo(bytes, i);
                        count++;
                    }
                }

                Assert.That(count, Is.GreaterThan(0), $"'{from}' not found in the fixture");
            }

            string path = Path.Combine(_dir, name);
            File.WriteAllBytes(path, bytes);
            return path;
        }
    }
}
