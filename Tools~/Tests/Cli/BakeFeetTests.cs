using System;
using System.IO;
using System.Text.Json;
using DeltaInterpolator.Core.Bvh;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary><c>bake --feet lock|off</c>: foot skating in the table and the JSON, locking both methods, keys untouched.</summary>
    public sealed class BakeFeetTests
    {
        private string _dir = "";

        private static string Root => TestEnvironment.RepositoryRoot!;

        private static string Sample => Path.Combine(Root, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        private static string Model => Path.Combine(Root, "Samples~", "LaFAN1Model", "DeltaInterpolator-LaFAN1.onnx");

        [SetUp]
        public void CreateFolder()
        {
            _dir = Path.Combine(Path.GetTempPath(), "inbetween-feet-" + Guid.NewGuid().ToString("N").Substring(0, 8));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void RemoveFolder() => Directory.Delete(_dir, true);

        [Test]
        public void LockingCutsBothMethodsSkatingAndLeavesTheKeysAsTheyAre()
        {
            (JsonDocument locked, BvhAnimation lockedModel) = Bake("lock");
            (JsonDocument off, BvhAnimation offModel) = Bake("off");
            using (locked)
            using (off)
            {
                Assert.That(locked.RootElement.GetProperty("feet").GetString(), Is.EqualTo("lock"));
                Assert.That(off.RootElement.GetProperty("feet").GetString(), Is.EqualTo("off"));
                double truth = locked.RootElement.GetProperty("ground_truth_foot_skating").GetDouble();
                Assert.That(locked.RootElement.GetProperty("foot_contact_samples").GetInt32(), Is.GreaterThan(100));
                Assert.That(truth, Is.EqualTo(off.RootElement.GetProperty("ground_truth_foot_skating").GetDouble()), "the truth does not depend on --feet");
                // Measured on this clip (keys every 60 frames = 15 model frames, LaFAN1 model): model 0.315 → 0.167 (0.53 ×),
                // SLERP 0.551 → 0.212 (0.38 ×), ground truth 0.073 leg lengths per second.
                foreach ((string method, double most) in new[] { ("model", 0.6), ("slerp", 0.5) })
                {
                    double on = Skating(locked, method), without = Skating(off, method);
                    Assert.That(without, Is.GreaterThan(truth), method);
                    Assert.That(on, Is.LessThanOrEqualTo(most * without), method);
                    double errorOn = Error(locked, method), errorOff = Error(off, method);
                    Assert.That(errorOn, Is.LessThanOrEqualTo(1.02 * errorOff), method + ": position error at most 2 % above --feet off");
                }
            }

            // Key frames: the input's exactly, with and without locking.
            var input = BvhReader.Read(Sample).Motion;
            using JsonDocument keysDoc = JsonDocument.Parse(File.ReadAllText(Path.Combine(_dir, "lock.json")));
            JsonElement keys = keysDoc.RootElement.GetProperty("keys");
            int first = keys[0].GetInt32(), j = input.Skeleton.JointCount;
            for (int i = 0; i < keys.GetArrayLength(); i++)
            {
                int k = keys[i].GetInt32();
                for (int v = 0; v < 4 * j; v++)
                {
                    Assert.That(lockedModel.Motion.LocalRotations[(k - first) * 4 * j + v], Is.EqualTo(offModel.Motion.LocalRotations[(k - first) * 4 * j + v]), $"key {k}: lock and off differ");
                }

                for (int joint = 0; joint < j; joint++)
                {
                    // The same rotation as the input's (a written Euler angle may differ by 360°, flipping the quaternion's sign).
                    double dot = 0;
                    for (int c = 0; c < 4; c++) dot += lockedModel.Motion.LocalRotations[((k - first) * j + joint) * 4 + c] * input.LocalRotations[(k * j + joint) * 4 + c];
                    Assert.That(Math.Abs(dot), Is.GreaterThan(1 - 1e-9), $"key {k}, joint {joint}: not the input's rotation");
                }
            }
        }

        [Test]
        public void AModelWhoseContactOutputHasTheWrongShapeIsRefusedInOneLine()
        {
            // The contact fixture with its head's Sigmoid turned into a Flatten (same length): foot_contacts [B, N·4].
            byte[] bytes = File.ReadAllBytes(Path.Combine(Root, "Tests", "Fixtures~", "tiny-model-contacts.onnx"));
            byte[] from = System.Text.Encoding.ASCII.GetBytes("Sigmoid"), to = System.Text.Encoding.ASCII.GetBytes("Flatten");
            int count = 0;
            for (int at = bytes.AsSpan().IndexOf(from); at >= 0; at = bytes.AsSpan().IndexOf(from), count++) to.CopyTo(bytes, at);
            Assert.That(count, Is.GreaterThan(0), "the contact head's Sigmoid (node name and operator)");
            string model = Path.Combine(_dir, "flat.onnx");
            File.WriteAllBytes(model, bytes);
            CliRun run = CliHarness.Run("bake", Sample, "--every", "60", "--model", model, "--out", Path.Combine(_dir, "o.bvh"));
            CliHarness.AssertOneErrorLine(run, "foot_contacts");
            Assert.That(File.Exists(Path.Combine(_dir, "o.bvh")), Is.False, "nothing written");
        }

        [Test]
        public void AModelWithContactsLocksWithThemAndSaysSo()
        {
            string json = Path.Combine(_dir, "contacts.json");
            CliRun run = CliHarness.Run("bake", Sample, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--model", Path.Combine(Root, "Tests", "Fixtures~", "tiny-model-contacts.onnx"),
                "--out", Path.Combine(_dir, "c.bvh"), "--json", json, "--preview", Path.Combine(_dir, "c.html"));
            CliHarness.AssertSuccess(run);
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(json));
            Assert.That(doc.RootElement.GetProperty("model_contacts").GetString(), Is.EqualTo("predicted"));
            Assert.That(run.Stdout.Replace("\n", " ").Replace("  ", " "), Does.Contain("the model's footprints are the contacts it predicted"), "the preview marks the predicted contacts");
            CliRun plain = CliHarness.Run("bake", Sample, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--model", Path.Combine(Root, "Tests", "Fixtures~", "tiny-model.onnx"),
                "--out", Path.Combine(_dir, "p.bvh"), "--json", Path.Combine(_dir, "p.json"), "--preview", Path.Combine(_dir, "p.html"));
            CliHarness.AssertSuccess(plain);
            using JsonDocument plainDoc = JsonDocument.Parse(File.ReadAllText(Path.Combine(_dir, "p.json")));
            Assert.That(plainDoc.RootElement.GetProperty("model_contacts").GetString(), Is.EqualTo("labelled"));
            Assert.That(plain.Stdout.Replace("\n", " ").Replace("  ", " "), Does.Not.Contain("contacts it predicted"));
        }

        [Test]
        public void AnythingButLockOrOffIsRefused()
        {
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", Sample, "--every", "60", "--out", Path.Combine(_dir, "o.bvh"), "--feet", "on"), "lock or off");
        }

        private (JsonDocument, BvhAnimation) Bake(string feet)
        {
            string json = Path.Combine(_dir, feet + ".json"), bvh = Path.Combine(_dir, feet + ".bvh");
            CliRun run = CliHarness.Run("bake", Sample, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--model", Model, "--feet", feet, "--out", bvh, "--json", json);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("foot skating:"));
            Assert.That(run.Stdout, Does.Contain("Ground"), "the ground truth's row (its name may wrap)");
            return (JsonDocument.Parse(File.ReadAllText(json)), BvhReader.Read(bvh));
        }

        private static double Skating(JsonDocument doc, string method) => doc.RootElement.GetProperty("methods").GetProperty(method).GetProperty("foot_skating").GetDouble();

        private static double Error(JsonDocument doc, string method) => doc.RootElement.GetProperty("methods").GetProperty(method).GetProperty("mean_position_error").GetDouble();
    }
}
