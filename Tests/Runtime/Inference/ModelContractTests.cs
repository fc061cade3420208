using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using DeltaInterpolator.Core.Inference;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Inference
{
    /// <summary>Contract checks on synthetic model descriptions (no engine needed).</summary>
    [TestFixture]
    public sealed class ModelContractTests
    {
        private const string Source = "Models/test.onnx";

        internal static string MetadataJson(string graph = "whole", int version = 1, string rotation6D = "rows", string inputMode = "last_pose", string outputMode = "slerp", string extra = "")
        {
            return "{\"contract_version\": " + version + ", \"name\": \"test\", \"graph\": \"" + graph + "\", " +
                   "\"skeleton\": {\"names\": [\"Hips\", \"Spine\", \"Head\"], \"parents\": [-1, 0, 1], \"offsets\": [[0,0,0],[0,10,0],[0,20,0]]}, " +
                   "\"unit_scale\": 0.01, \"up_axis\": [0, 1, 0], \"facing_local_axis\": [0, 1, 0], \"facing_target_axis\": [1, 0, 0], " +
                   "\"rotation_6d\": \"" + rotation6D + "\", \"quaternion_order\": \"wxyz\", \"output_delta_mode\": \"" + outputMode + "\", " +
                   "\"input_delta_mode\": \"" + inputMode + "\", " + extra +
                   "\"training\": {\"past_frames\": [10, 10], \"future_frames\": [1, 1], \"missing_frames\": [5, 39], \"fps\": 30}, " +
                   "\"max_frame_index\": 255, \"architecture\": {\"width\": 32, \"blocks\": 2, \"heads\": 4, \"embedding_dim\": 32, \"embedding_size\": 256, \"parameters\": 1000}}";
        }

        internal static ModelDescription Whole(string? json = null, string versionText = "1", bool withQueryFeatures = false)
        {
            var inputs = new List<TensorDescription>
            {
                new TensorDescription("key_features", TensorElementKind.Float32, new long[] { 1, -1, 27 }),
                new TensorDescription("key_frame_indices", TensorElementKind.Int64, new long[] { -1 }),
                new TensorDescription("query_frame_indices", TensorElementKind.Int64, new long[] { -1 }),
                new TensorDescription("gap_length", TensorElementKind.Int64, new long[] { 1 }),
            };
            if (withQueryFeatures) inputs.Add(new TensorDescription("query_features", TensorElementKind.Float32, new long[] { 1, -1, 27 }));
            var outputs = new List<TensorDescription>
            {
                new TensorDescription("root_position_delta", TensorElementKind.Float32, new long[] { 1, -1, 3 }),
                new TensorDescription("rotation_6d_delta", TensorElementKind.Float32, new long[] { 1, -1, 3, 6 }),
                new TensorDescription("contract_version", TensorElementKind.Int64, new long[] { 1 }),
                new TensorDescription("joint_count", TensorElementKind.Int64, new long[] { 1 }),
                new TensorDescription("key_feature_size", TensorElementKind.Int64, new long[] { 1 }),
            };
            var metadata = new Dictionary<string, string> { ["contract_version"] = versionText, ["deltainterp"] = json ?? MetadataJson() };
            return new ModelDescription(Source, inputs, outputs, metadata);
        }

        [Test]
        public void AValidDescriptionIsRead()
        {
            ModelContract c = ModelContract.Read(Whole(), ModelGraphKind.Whole);
            Assert.That(c.JointCount, Is.EqualTo(3));
            Assert.That(c.KeyFeatureSize, Is.EqualTo(27));
            Assert.That(c.UnitScale, Is.EqualTo(0.01));
            Assert.That(c.OutputDeltaMode, Is.EqualTo(OutputDeltaMode.Slerp));
            Assert.That(c.Architecture.Width, Is.EqualTo(32));
            Assert.That(c.TrainingMissingFrames, Is.EqualTo((5, 39)));
        }

        [Test]
        public void NewerVersionIsRefusedWithWhatToDo()
        {
            string m = Refuse(Whole(MetadataJson(version: 4), versionText: "4"));
            Assert.That(m, Is.EqualTo(Source + ": the model has contract version 4; expected a version from 1 to 3; update the package, or export the model with a trainer of the matching version"));
        }

        [Test]
        public void MissingMetadataIsRefused()
        {
            var d = Whole();
            var bare = new ModelDescription(Source, d.Inputs, d.Outputs, new Dictionary<string, string>());
            Assert.That(Refuse(bare), Does.Contain("no 'deltainterp' metadata"));
        }

        [Test]
        public void MalformedMetadataIsRefused()
        {
            Assert.That(Refuse(Whole("{\"contract_version\": 1,")), Does.Contain("not a valid JSON object"));
        }

        [Test]
        public void MissingFieldIsNamed()
        {
            string json = MetadataJson().Replace("\"unit_scale\": 0.01, ", "");
            Assert.That(Refuse(Whole(json)), Does.Contain("has no \"unit_scale\""));
        }

        [Test]
        public void ColumnSixDIsRefused()
        {
            Assert.That(Refuse(Whole(MetadataJson(rotation6D: "columns"))), Does.Contain("rotation_6d is 'columns'"));
        }

        [Test]
        public void AblationInputModeIsRefused()
        {
            Assert.That(Refuse(Whole(MetadataJson(inputMode: "none"), withQueryFeatures: true)), Does.Contain("input delta mode 'none'"));
        }

        [Test]
        public void UnexpectedInputIsRefused()
        {
            Assert.That(Refuse(Whole(withQueryFeatures: true)), Does.Contain("'query_features' input"));
        }

        [Test]
        public void WrongGraphKindIsRefused()
        {
            Assert.That(Refuse(Whole(MetadataJson(graph: "frame"))), Does.Contain("holds the 'frame' graph"));
        }

        [Test]
        public void ConstantOutputsMustAgreeWithMetadata()
        {
            ModelContract c = ModelContract.Read(Whole(), ModelGraphKind.Whole);
            Assert.DoesNotThrow(() => c.CheckConstants(1, 3, 27));
            var e = Assert.Throws<ModelContractException>(() => c.CheckConstants(1, 4, 36))!;
            Assert.That(e.Message, Does.Contain("joint_count output is 4 but its metadata skeleton has 3 joints"));
            e = Assert.Throws<ModelContractException>(() => c.CheckConstants(2, 3, 27))!;
            Assert.That(e.Message, Does.Contain("contract_version output is 2"));
        }

        [Test]
        public void VersionMatchesThePythonTrainer()
        {
            string? dir = AppContext.BaseDirectory;
            string? contract = null;
            while (dir != null && contract == null)
            {
                string candidate = Path.Combine(dir, "Training", "Python~", "deltainterp", "contract.py");
                if (File.Exists(candidate)) contract = candidate;
                dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
            }

            if (contract == null) Assert.Ignore("Training/Python~/deltainterp/contract.py not found (package installed without Training/)");
            Match m = Regex.Match(File.ReadAllText(contract!), @"^CONTRACT_VERSION\s*=\s*(\d+)", RegexOptions.Multiline);
            Assert.That(m.Success, Is.True, "CONTRACT_VERSION in contract.py");
            Assert.That(int.Parse(m.Groups[1].Value), Is.EqualTo(ModelContract.Version));
        }

        private static string Refuse(ModelDescription d)
        {
            var e = Assert.Throws<ModelContractException>(() => ModelContract.Read(d, ModelGraphKind.Whole))!;
            Assert.That(e.Message, Does.StartWith(Source + ": "));
            Assert.That(e.Message, Does.Contain("; expected"));
            return e.Message;
        }
    }
}
