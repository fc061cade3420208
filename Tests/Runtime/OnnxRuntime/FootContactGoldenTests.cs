using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Contract version 3's <c>foot_contacts</c> read the same in C# as in Python: the tiny fixture with a contact head
    /// (<c>python3 -m deltainterp fixtures</c>) on ONNX Runtime reproduces the golden vectors' contact probabilities to
    /// 1e-5 through the whole graph and frame by frame through the lazy graphs, beside the motion itself.
    /// </summary>
    [TestFixture]
    public sealed class FootContactGoldenTests
    {
        private const double ContactTolerance = 1e-5;

        private Inbetweener _model = null!;

        [OneTimeSetUp]
        public void Load() => _model = OnnxRuntimeInbetweener.Load(Fixtures.TinyContactModel, requireLazy: true);

        [OneTimeTearDown]
        public void Unload() => _model?.Dispose();

        public static IEnumerable<TestCaseData> Cases()
        {
            foreach (GoldenCase c in Fixtures.GoldenContacts) yield return new TestCaseData(c).SetName("GoldenContacts_" + c.Name);
        }

        [Test]
        public void TheFixtureHasContactsOnEveryCase()
        {
            Assert.That(_model.Contract.HasFootContacts, Is.True);
            Assert.That(Fixtures.GoldenContacts.Count, Is.GreaterThanOrEqualTo(4));
            foreach (GoldenCase c in Fixtures.GoldenContacts) Assert.That(c.FootContacts, Has.Length.EqualTo(4 * c.MissingFrames), c.Name);
        }

        [TestCaseSource(nameof(Cases))]
        public void WholeGraphContactsMatchPyTorch(GoldenCase c)
        {
            Transition t = c.ToTransition(_model.Contract.Skeleton);
            _model.Inbetween(t);
            double contacts = GoldenParityTests.MaxAbs(t.FootContacts, c.FootContacts!);
            double rotations = GoldenParityTests.MaxQuaternionDistance(t.LocalRotations, c.LocalQuaternions);
            TestContext.Out.WriteLine($"{c.Name}: foot_contacts {contacts:E2}, local rotations {rotations:E2}");
            Assert.That(t.HasFootContacts, Is.True);
            Assert.That(t.ContactThreshold, Is.EqualTo(_model.Contract.ContactThreshold));
            Assert.That(contacts, Is.LessThan(ContactTolerance), "foot_contacts");
            Assert.That(rotations, Is.LessThan(1e-4), "local rotations");
        }

        [TestCaseSource(nameof(Cases))]
        public void LazyFrameContactsMatchPyTorch(GoldenCase c)
        {
            Transition t = c.ToTransition(_model.Contract.Skeleton);
            LazyInbetweener decoder = _model.CreateLazy(c.PastFrames, c.MissingFrames);
            decoder.Begin(t);
            for (int k = c.MissingFrames - 1; k >= 0; k--) decoder.DecodeFrame(k);
            double contacts = GoldenParityTests.MaxAbs(t.FootContacts, c.FootContacts!);
            TestContext.Out.WriteLine($"{c.Name}: lazy foot_contacts {contacts:E2}");
            Assert.That(contacts, Is.LessThan(ContactTolerance), "foot_contacts");
        }

        [Test]
        public void ABakeCarriesThePredictionsOfEveryFilledFrameAndNoneOfItsKeys()
        {
            string file = Path.Combine(TestEnvironment.RequireLafan1(), "walk4_subject1.bvh");
            MotionClip clip = BvhReader.Read(file).Motion.Excerpt(0, 200);
            int[] keys = KeyFrames.Every(15, clip.FrameCount);
            var model = new ClipBaker(_model, BakeSettings.ForModel(_model.Contract));
            model.Bake(clip, model.Plan(clip.FrameCount, keys));
            var slerp = new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline());
            slerp.Bake(clip, slerp.Plan(clip.FrameCount, keys));
            FootContacts contacts = model.Contacts;
            Assert.That(contacts.FrameCount, Is.EqualTo(keys[keys.Length - 1] - keys[0] + 1));
            Assert.That(contacts.Threshold, Is.EqualTo(_model.Contract.ContactThreshold));
            for (int f = 0; f < contacts.FrameCount; f++) Assert.That(contacts.IsPredicted(f), Is.EqualTo(Array.IndexOf(keys, f + keys[0]) < 0), $"frame {f}");
            Assert.That(slerp.Contacts.AnyPredicted, Is.False, "SLERP always leaves contacts to the labels");
        }

        [Test]
        public void AModelWithoutContactsLeavesTheTransitionWithoutPredictions()
        {
            using Inbetweener plain = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            GoldenCase c = Fixtures.Golden[0];
            Transition t = c.ToTransition(plain.Contract.Skeleton);
            t.HasFootContacts = true;
            plain.Inbetween(t);
            Assert.That(plain.Contract.HasFootContacts, Is.False);
            Assert.That(t.HasFootContacts, Is.False);
        }
    }
}
