using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The C# pipeline on ONNX Runtime reproduces the PyTorch pipeline on every golden vector of
    /// Tests/Fixtures~: localization, key features, raw network outputs, final rotations, root and joint
    /// positions; and lazily decoded frames equal whole-transition frames.
    /// </summary>
    [TestFixture]
    public sealed class GoldenParityTests
    {
        private const double NetworkTolerance = 1e-4;
        private const double RotationTolerance = 1e-4;
        private const double ModelUnitTolerance = 1e-4;
        private const double LazyTolerance = 1e-5;

        private Inbetweener _model = null!;

        [OneTimeSetUp]
        public void Load() => _model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);

        [OneTimeTearDown]
        public void Unload() => _model?.Dispose();

        public static IEnumerable<TestCaseData> Cases()
        {
            foreach (GoldenCase c in Fixtures.Golden) yield return new TestCaseData(c).SetName("Golden_" + c.Name);
        }

        [Test]
        public void FixturesCoverShortMediumAndLongGaps()
        {
            Assert.That(Fixtures.Golden.Count, Is.GreaterThanOrEqualTo(4));
            Assert.That(_model.SupportsLazyDecoding, Is.True);
            Assert.That(_model.Contract.JointCount, Is.EqualTo(22));
        }

        [TestCaseSource(nameof(Cases))]
        public void PipelineMatchesPyTorch(GoldenCase c)
        {
            int j = _model.Contract.JointCount;
            Transition t = c.ToTransition(_model.Contract.Skeleton);
            var global = new double[c.Gap * j * 3];
            _model.Inbetween(t, global);

            Localization loc = _model.LastLocalization;
            double yawSign = Math.Sign(loc.Yaw.W * c.Yaw[0] + loc.Yaw.X * c.Yaw[1] + loc.Yaw.Y * c.Yaw[2] + loc.Yaw.Z * c.Yaw[3]);
            Assert.That(MaxAbs(new[] { loc.Yaw.W, loc.Yaw.X, loc.Yaw.Y, loc.Yaw.Z }, c.Yaw, yawSign), Is.LessThan(1e-7), "localization yaw");
            Assert.That(MaxAbs(new[] { loc.Origin.X, loc.Origin.Y, loc.Origin.Z }, c.Origin), Is.LessThan(1e-6), "localization origin");

            double features = MaxAbs(_model.LastKeyFeatures, c.KeyFeatures);
            double rootDelta = MaxAbs(_model.LastRootPositionDelta, c.RootPositionDelta);
            double rotationDelta = MaxAbs(_model.LastRotation6DDelta, c.Rotation6DDelta);
            double rotations = MaxQuaternionDistance(t.LocalRotations, c.LocalQuaternions);
            double scale = _model.Contract.UnitScale;
            double roots = MaxAbs(t.RootPositions, c.RootPositions) * scale;
            double joints = MaxAbs(global, c.GlobalPositions) * scale;
            TestContext.Out.WriteLine($"{c.Name}: key_features {features:E2}, root_position_delta {rootDelta:E2}, rotation_6d_delta {rotationDelta:E2}, " +
                $"local rotations {rotations:E2}, root positions {roots:E2} m, global positions {joints:E2} m");
            Assert.That(features, Is.LessThan(1e-5), "key_features");
            Assert.That(rootDelta, Is.LessThan(NetworkTolerance), "root_position_delta");
            Assert.That(rotationDelta, Is.LessThan(NetworkTolerance), "rotation_6d_delta");
            Assert.That(rotations, Is.LessThan(RotationTolerance), "local rotations");
            Assert.That(roots, Is.LessThan(ModelUnitTolerance), "root positions (model units)");
            Assert.That(joints, Is.LessThan(ModelUnitTolerance), "global positions (model units)");
        }

        [TestCaseSource(nameof(Cases))]
        public void LazyFramesEqualWholeTransition(GoldenCase c)
        {
            Transition whole = c.ToTransition(_model.Contract.Skeleton);
            _model.Inbetween(whole);
            Transition lazy = c.ToTransition(_model.Contract.Skeleton);
            LazyInbetweener decoder = _model.CreateLazy(c.PastFrames, c.Gap);
            decoder.Begin(lazy);
            // Out of order on purpose: a frame depends on the keys only.
            for (int k = c.Gap - 1; k >= 0; k--) decoder.DecodeFrame(k);

            double rotations = MaxAbs(lazy.LocalRotations, whole.LocalRotations);
            double roots = MaxAbs(lazy.RootPositions, whole.RootPositions) * _model.Contract.UnitScale;
            TestContext.Out.WriteLine($"{c.Name}: lazy vs whole: rotations {rotations:E2}, root positions {roots:E2} m");
            Assert.That(rotations, Is.LessThan(LazyTolerance), "local rotations");
            Assert.That(roots, Is.LessThan(LazyTolerance), "root positions (model units)");
        }

        [Test]
        public void RepeatedCallsGiveIdenticalResults()
        {
            GoldenCase c = Fixtures.Golden[Fixtures.Golden.Count - 1];
            Transition t = c.ToTransition(_model.Contract.Skeleton);
            _model.Inbetween(t);
            var first = (double[])t.LocalRotations.Clone();
            _model.Inbetween(c.ToTransition(_model.Contract.Skeleton));
            _model.Inbetween(t);
            Assert.That(t.LocalRotations, Is.EqualTo(first));
        }

        public static double MaxAbs(ReadOnlySpan<double> a, ReadOnlySpan<double> b, double signOfB = 1.0)
        {
            Assert.That(a.Length, Is.EqualTo(b.Length), "lengths");
            double worst = 0;
            for (int i = 0; i < a.Length; i++) worst = Math.Max(worst, Math.Abs(a[i] - signOfB * b[i]));
            return worst;
        }

        public static double MaxAbs(ReadOnlySpan<float> a, ReadOnlySpan<double> b)
        {
            Assert.That(a.Length, Is.EqualTo(b.Length), "lengths");
            double worst = 0;
            for (int i = 0; i < a.Length; i++) worst = Math.Max(worst, Math.Abs(a[i] - b[i]));
            return worst;
        }

        /// <summary>Largest |q − g| over all quaternions, sign-insensitive (min over q and −q).</summary>
        internal static double MaxQuaternionDistance(double[] a, double[] b)
        {
            Assert.That(a.Length, Is.EqualTo(b.Length), "lengths");
            double worst = 0;
            for (int i = 0; i < a.Length; i += 4)
            {
                double plus = 0, minus = 0;
                for (int c = 0; c < 4; c++)
                {
                    plus = Math.Max(plus, Math.Abs(a[i + c] - b[i + c]));
                    minus = Math.Max(minus, Math.Abs(a[i + c] + b[i + c]));
                }

                worst = Math.Max(worst, Math.Min(plus, minus));
            }

            return worst;
        }
    }
}
