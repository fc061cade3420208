using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Json;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Inference
{
    /// <summary>
    /// The contract as data: ToJson writes every field it read, so an engine asset can keep the JSON and
    /// rebuild the same contract (Parse(ToJson(c)) equals c; the JSON equals the exported object).
    /// </summary>
    [TestFixture]
    public sealed class ModelContractJsonTests
    {
        [Test]
        public void TheSyntheticContractRoundTrips()
        {
            ModelContract c = ModelContract.Read(ModelContractTests.Whole(), ModelGraphKind.Whole);
            RoundTrip(c, ModelContractTests.MetadataJson());
        }

        [TestCase("Tests/Fixtures~/tiny-model.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.keys.onnx")]
        [TestCase("Tests/Fixtures~/tiny-model.frame.onnx")]
        [TestCase("Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx")]
        public void AnExportedContractRoundTrips(string relative)
        {
            string path = Repository(relative);
            IReadOnlyDictionary<string, string> metadata = OnnxMetadataReader.Read(path);
            var report = new ModelCheckReport();
            ModelContract c = ModelContract.FromMetadata(path, metadata, report)!;
            Assert.That(report.HasErrors, Is.False);
            RoundTrip(c, metadata[TensorNames.DescriptionMetadata]);
            // What an asset-backed backend passes: the stored contract as metadata reads back the same.
            var again = new ModelCheckReport();
            ModelContract fromAsset = ModelContract.FromMetadata("asset", c.ToMetadata(), again)!;
            Assert.That(again.HasErrors, Is.False);
            Assert.That(fromAsset.ToJson(), Is.EqualTo(c.ToJson()));
            Assert.That(c.ToMetadata()[TensorNames.ContractVersionMetadata], Is.EqualTo(metadata[TensorNames.ContractVersionMetadata]));
        }

        [TestCase("Tests/Fixtures~/tiny-model.keys.onnx", ModelGraphKind.Keys)]
        [TestCase("Tests/Fixtures~/tiny-model.frame.onnx", ModelGraphKind.Frame)]
        public void TheWholeContractForAnotherGraphIsThatGraphsContract(string relative, ModelGraphKind kind)
        {
            // An engine asset keeps the whole graph's contract once; the Sentis factory describes the keys
            // and frame graphs with ForGraph(kind): it must equal what those exported files carry.
            ModelContract whole = ModelContract.FromMetadata("whole", OnnxMetadataReader.Read(Repository("Tests/Fixtures~/tiny-model.onnx")), new ModelCheckReport())!;
            ModelContract exported = ModelContract.FromMetadata("other", OnnxMetadataReader.Read(Repository(relative)), new ModelCheckReport())!;
            ModelContract forGraph = whole.ForGraph(kind);
            Assert.That(forGraph.Graph, Is.EqualTo(kind));
            Assert.That(whole.Graph, Is.EqualTo(ModelGraphKind.Whole), "the original is unchanged");
            Assert.That(forGraph.ToJson(), Is.EqualTo(exported.ToJson()));
            var report = new ModelCheckReport();
            ModelContract read = ModelContract.FromMetadata("asset", forGraph.ToMetadata(), report)!;
            ModelChecks.GraphKind(read, kind, report);
            Assert.That(report.HasErrors, Is.False, string.Join("; ", report));
        }

        [Test]
        public void FromJsonRefusesAnInvalidContract()
        {
            var e = Assert.Throws<ModelContractException>(() => ModelContract.FromJson("{\"contract_version\": 1}", "Assets/Model.asset"))!;
            Assert.That(e.Message, Does.StartWith("Assets/Model.asset: metadata 'deltainterp' has no \"graph\"; expected"));
        }

        private static void RoundTrip(ModelContract c, string exported)
        {
            string json = c.ToJson();
            ModelContract back = ModelContract.FromJson(json, c.Source);
            Assert.That(back.ToJson(), Is.EqualTo(json), "ToJson is stable");
            Assert.That(back.ContractVersion, Is.EqualTo(c.ContractVersion));
            Assert.That(back.Name, Is.EqualTo(c.Name));
            Assert.That(back.Graph, Is.EqualTo(c.Graph));
            Assert.That(back.Skeleton.Names, Is.EqualTo(c.Skeleton.Names));
            Assert.That(back.Skeleton.Parents, Is.EqualTo(c.Skeleton.Parents));
            Assert.That(back.Skeleton.Offsets, Is.EqualTo(c.Skeleton.Offsets));
            Assert.That(back.UnitScale, Is.EqualTo(c.UnitScale));
            Assert.That(back.FacingLocalAxis, Is.EqualTo(c.FacingLocalAxis));
            Assert.That(back.FacingTargetAxis, Is.EqualTo(c.FacingTargetAxis));
            Assert.That(back.OutputDeltaMode, Is.EqualTo(c.OutputDeltaMode));
            Assert.That(back.InputDeltaMode, Is.EqualTo(c.InputDeltaMode));
            Assert.That(back.MaxFrameIndex, Is.EqualTo(c.MaxFrameIndex));
            Assert.That(back.TrainingPastFrames, Is.EqualTo(c.TrainingPastFrames));
            Assert.That(back.TrainingFutureFrames, Is.EqualTo(c.TrainingFutureFrames));
            Assert.That(back.TrainingMissingFrames, Is.EqualTo(c.TrainingMissingFrames));
            Assert.That(back.TrainingFps, Is.EqualTo(c.TrainingFps));
            Assert.That(back.TrainingData, Is.EqualTo(c.TrainingData));
            // A record: every field compared, and a failure prints both architectures in full.
            Assert.That(back.Architecture, Is.EqualTo(c.Architecture));
            // Nothing lost against what the exporter wrote: the same JSON values, member by member.
            SameJson(JsonValue.Parse(json, "ToJson"), JsonValue.Parse(exported, "exported"), "$");
        }

        private static void SameJson(JsonValue a, JsonValue b, string path)
        {
            Assert.That(a.Kind, Is.EqualTo(b.Kind), path);
            switch (a.Kind)
            {
                case JsonKind.Number:
                    Assert.That(a.ExpectNumber(path), Is.EqualTo(b.ExpectNumber(path)), path);
                    break;
                case JsonKind.String:
                    Assert.That(a.ExpectString(path), Is.EqualTo(b.ExpectString(path)), path);
                    break;
                case JsonKind.Array:
                    IReadOnlyList<JsonValue> x = a.ExpectArray(path), y = b.ExpectArray(path);
                    Assert.That(x.Count, Is.EqualTo(y.Count), path);
                    for (int i = 0; i < x.Count; i++) SameJson(x[i], y[i], path + "[" + i.ToString(CultureInfo.InvariantCulture) + "]");
                    break;
                case JsonKind.Object:
                    IReadOnlyDictionary<string, JsonValue> p = a.ExpectObject(path), q = b.ExpectObject(path);
                    Assert.That(p.Keys, Is.EquivalentTo(q.Keys), path);
                    foreach (KeyValuePair<string, JsonValue> kv in p) SameJson(kv.Value, q[kv.Key], path + "." + kv.Key);
                    break;
            }
        }

        /// <summary>A path from the repository root (found above the test binaries).</summary>
        public static string Repository(string relative)
        {
            string? dir = AppContext.BaseDirectory;
            while (dir != null)
            {
                string candidate = Path.Combine(dir, relative);
                if (File.Exists(candidate)) return candidate;
                dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar));
            }

            Assert.Fail(relative + " not found above " + AppContext.BaseDirectory);
            return "";
        }
    }
}
