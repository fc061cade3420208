using System;
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
            string path = Patched("v3.onnx", ("contract_version\u0012\u00012", "contract_version\u0012\u00013"), ("\"contract_version\": 2", "\"contract_version\": 3"));
            string message = Refusal(path);
            Assert.That(message, Does.Contain("contract version 3"));
            Assert.That(message, Does.Contain("expected a version from 1 to 2"));
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
        private string Patched(string name, params (string From, string To)[] edits)
        {
            byte[] bytes = File.ReadAllBytes(Fixtures.TinyModel);
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
