using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Inference
{
    /// <summary>
    /// The checks report every problem with a severity and a remedy instead of throwing at the first;
    /// loading still refuses a model with any error (ModelContractTests).
    /// </summary>
    [TestFixture]
    public sealed class ModelChecksTests
    {
        private static ModelContract Valid() => ModelContract.Read(ModelContractTests.Whole(), ModelGraphKind.Whole);

        private static ModelCheckReport CheckModel(ModelDescription d)
        {
            var report = new ModelCheckReport();
            ModelChecks.Model(d, ModelGraphKind.Whole, report);
            foreach (ModelCheck c in report) TestContext.Out.WriteLine(c);
            return report;
        }

        [Test]
        public void AValidModelHasNoErrorsOrWarnings()
        {
            ModelCheckReport r = CheckModel(ModelContractTests.Whole());
            Assert.That(r.HasErrors, Is.False);
            Assert.That(r.HasWarnings, Is.False);
        }

        [Test]
        public void VersionOutsideTheSupportedRangeIsOneErrorWithARemedy()
        {
            ModelCheckReport r = CheckModel(ModelContractTests.Whole(ModelContractTests.MetadataJson(version: 4), versionText: "4"));
            Assert.That(r.CountOf(CheckSeverity.Error), Is.EqualTo(1), "the string and the JSON say the same: one result");
            ModelCheck e = r.FirstError!;
            Assert.That(e.Message, Is.EqualTo("the model has contract version 4"));
            Assert.That(e.Remedy, Is.EqualTo("expected a version from 1 to 3; update the package, or export the model with a trainer of the matching version"));
            Assert.That(e.Source, Is.EqualTo("Models/test.onnx"));

            r = CheckModel(ModelContractTests.Whole(ModelContractTests.MetadataJson(version: 0), versionText: "0"));
            Assert.That(r.FirstError!.Remedy, Does.Contain("export the checkpoint again with the current trainer"));
        }

        [Test]
        public void MissingMetadataIsAnError()
        {
            var d = ModelContractTests.Whole();
            var report = new ModelCheckReport();
            ModelContract? c = ModelChecks.Model(new ModelDescription("m.onnx", d.Inputs, d.Outputs, new Dictionary<string, string>()), ModelGraphKind.Whole, report);
            Assert.That(c, Is.Null);
            Assert.That(report.Count, Is.EqualTo(1));
            Assert.That(report[0].Severity, Is.EqualTo(CheckSeverity.Error));
            Assert.That(report[0].Message, Is.EqualTo("the model has no 'deltainterp' metadata"));
            Assert.That(report[0].Remedy, Does.Contain("python3 -m deltainterp export"));
        }

        [Test]
        public void EveryMissingOrUnsupportedFieldIsListedNotOnlyTheFirst()
        {
            string json = ModelContractTests.MetadataJson(rotation6D: "columns").Replace("\"unit_scale\": 0.01, ", "").Replace("\"quaternion_order\": \"wxyz\"", "\"quaternion_order\": \"xyzw\"");
            ModelCheckReport r = CheckModel(ModelContractTests.Whole(json));
            var messages = new List<string>();
            foreach (ModelCheck c in r)
            {
                if (c.Severity == CheckSeverity.Error) messages.Add(c.Message);
            }

            Assert.That(messages, Is.EquivalentTo(new[]
            {
                "metadata 'deltainterp' has no \"unit_scale\"",
                "metadata rotation_6d is 'columns'",
                "metadata quaternion_order is 'xyzw'",
            }));
        }

        [Test]
        public void JointCountDifferenceIsOneError()
        {
            var report = new ModelCheckReport();
            var two = new Skeleton(new[] { "Hips", "Spine" }, new[] { -1, 0 }, new double[6]);
            ModelChecks.Skeleton(Valid(), two, "char.bvh", report);
            Assert.That(report.Count, Is.EqualTo(1));
            Assert.That(report[0].Severity, Is.EqualTo(CheckSeverity.Error));
            Assert.That(report[0].Message, Is.EqualTo("the model has 3 joints but char.bvh has 2"));
            Assert.That(report[0].Remedy, Does.Contain("retarget"));
        }

        [Test]
        public void EveryJointWithAnotherNameOrParentIsReported()
        {
            var report = new ModelCheckReport();
            var other = new Skeleton(new[] { "Root", "Spine", "Skull" }, new[] { -1, 0, 1 }, new double[9]);
            ModelChecks.Skeleton(Valid(), other, "the character", report);
            Assert.That(report.Count, Is.EqualTo(2));
            Assert.That(report[0].Message, Is.EqualTo("joint 0 is 'Hips' in the model but 'Root' in the character"));
            Assert.That(report[1].Message, Is.EqualTo("joint 2 is 'Head' in the model but 'Skull' in the character"));

            report.Clear();
            var reparented = new Skeleton(new[] { "Hips", "Spine", "Head" }, new[] { -1, 0, 0 }, new double[9]);
            ModelChecks.Skeleton(Valid(), reparented, "the character", report);
            Assert.That(report.Count, Is.EqualTo(1));
            Assert.That(report[0].Message, Is.EqualTo("joint 2 ('Head') has parent 1 in the model but 0 in the character"));

            var e = Assert.Throws<ModelContractException>(() => Valid().CheckSkeleton(other, "the character"))!;
            Assert.That(e.Message, Is.EqualTo("Models/test.onnx: joint 0 is 'Hips' in the model but 'Root' in the character; expected the same joint names in the same order; rename or reorder the joints, or train a model on this skeleton"));
        }

        [Test]
        public void ConstantOutputsDisagreeingWithTheMetadataAreErrors()
        {
            var report = new ModelCheckReport();
            ModelChecks.Constants(Valid(), 1, 3, 27, report);
            Assert.That(report.Count, Is.EqualTo(0));
            ModelChecks.Constants(Valid(), 1, 4, 36, report);
            Assert.That(report.Count, Is.EqualTo(2));
            Assert.That(report[0].Message, Is.EqualTo("the graph's joint_count output is 4 but its metadata skeleton has 3 joints"));
            Assert.That(report[1].Message, Is.EqualTo("the graph's key_feature_size output is 36"));
        }

        [Test]
        public void RequestsOutsideTheTrainedRangesAreWarnings()
        {
            // Trained on P = 10 and gaps of 5..39 (ModelContractTests.MetadataJson).
            ModelContract c = Valid();
            var report = new ModelCheckReport();
            ModelChecks.Request(c, 10, 30, report);
            Assert.That(report.Count, Is.EqualTo(0), "inside the ranges");

            ModelChecks.Request(c, 5, 60, report);
            Assert.That(report.HasErrors, Is.False);
            Assert.That(report.Count, Is.EqualTo(2));
            Assert.That(report[0].Severity, Is.EqualTo(CheckSeverity.Warning));
            Assert.That(report[0].Message, Is.EqualTo("the request has 5 past key frames but the model was trained with 10"));
            Assert.That(report[0].Remedy, Does.StartWith("expected P in [10, 10]"));
            Assert.That(report[1].Severity, Is.EqualTo(CheckSeverity.Warning));
            Assert.That(report[1].Message, Is.EqualTo("the request has a gap of 60 frames but the model was trained on gaps of 5 to 39 frames"));
            Assert.That(report[1].Remedy, Does.Contain("split the gap"));
        }

        [Test]
        public void RequestsBeyondTheFrameEmbeddingsAreErrors()
        {
            var report = new ModelCheckReport();
            ModelChecks.Request(Valid(), 10, 246, report);
            Assert.That(report.FirstError, Is.Not.Null);
            Assert.That(report.FirstError!.Message, Is.EqualTo("P + n = 10 + 246 = 256 exceeds the model's largest frame index 255"));
            report.Clear();
            ModelChecks.Request(Valid(), 10, 245, report);
            Assert.That(report.HasErrors, Is.False);
            report.Clear();
            ModelChecks.Request(Valid(), 0, 5, report);
            Assert.That(report.HasErrors, Is.True);
        }

        [Test]
        public void WithoutTrainingRangesRequestsAreNotWarnedAboutAndTheReportSaysSo()
        {
            string json = ModelContractTests.MetadataJson().Replace("\"training\": {\"past_frames\": [10, 10], \"future_frames\": [1, 1], \"missing_frames\": [5, 39], \"fps\": 30}, ", "");
            ModelCheckReport r = CheckModel(ModelContractTests.Whole(json));
            Assert.That(r.HasErrors, Is.False);
            Assert.That(r.Count, Is.EqualTo(1));
            Assert.That(r[0].Severity, Is.EqualTo(CheckSeverity.Info));
            ModelContract c = ModelContract.Read(ModelContractTests.Whole(json), ModelGraphKind.Whole);
            var report = new ModelCheckReport();
            ModelChecks.Request(c, 3, 100, report);
            Assert.That(report.Count, Is.EqualTo(0));
        }
    }
}
