using System;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Inference
{
    /// <summary>Localization, baseline and decoding: properties that must hold whatever the network.</summary>
    [TestFixture]
    public sealed class PipelineMathTests
    {
        private static ModelContract Contract() => ModelContract.Read(ModelContractTests.Whole(), ModelGraphKind.Whole);

        [Test]
        public void LocalizationTurnsTheLastKeyToFaceTargetAxisAndIsInvertible()
        {
            ModelContract c = Contract();
            var random = new Random(7);
            for (int trial = 0; trial < 50; trial++)
            {
                QuaternionD root = Quaternions.Normalize(new QuaternionD(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5));
                var positions = new double[] { 100 * random.NextDouble(), 90, -300 * random.NextDouble() };
                var rotations = new double[12];
                root.Write(rotations, 0);
                QuaternionD.Identity.Write(rotations, 4);
                QuaternionD.Identity.Write(rotations, 8);
                var lp = new double[3];
                var lr = new double[12];
                Localization loc = Localizer.Localize(c, positions, rotations, 1, 0, lp, lr);

                Vector3D facing = Quaternions.Apply(QuaternionD.Read(lr, 0), c.FacingLocalAxis);
                Vector3D horizontal = new Vector3D(facing.X, 0, facing.Z);
                Assert.That(horizontal.Z / horizontal.Length, Is.EqualTo(0).Within(1e-9), "faces +X");
                Assert.That(horizontal.X, Is.GreaterThan(0), "faces +X, not −X");
                Assert.That(lp[0], Is.EqualTo(0).Within(1e-12));
                Assert.That(lp[1], Is.EqualTo(0.9).Within(1e-12), "height kept, in model units");
                Assert.That(lp[2], Is.EqualTo(0).Within(1e-12));

                Vector3D back = loc.UnlocalizePosition(Vector3D.Read(lp, 0));
                QuaternionD backRoot = loc.UnlocalizeRootRotation(QuaternionD.Read(lr, 0));
                Assert.That((back - Vector3D.Read(positions, 0)).Length, Is.LessThan(1e-9));
                Assert.That(Math.Abs(Quaternions.Dot(backRoot, root)), Is.EqualTo(1).Within(1e-12));
            }
        }

        [Test]
        public void ZeroDeltaDecodesToTheBaseline()
        {
            var zero = new float[6];
            var random = new Random(3);
            for (int trial = 0; trial < 100; trial++)
            {
                QuaternionD q = Quaternions.Normalize(new QuaternionD(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5));
                QuaternionD decoded = OutputDecoder.Rotation(OutputDeltaMode.Slerp, q, zero);
                Assert.That(Quaternions.Dot(decoded, q), Is.EqualTo(1).Within(1e-12), "same rotation and the baseline's hemisphere");
            }
        }

        [Test]
        public void DecodedQuaternionsStayInTheBaselineHemisphere()
        {
            var random = new Random(5);
            var delta = new float[6];
            for (int trial = 0; trial < 200; trial++)
            {
                QuaternionD q = Quaternions.Normalize(new QuaternionD(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5));
                for (int i = 0; i < 6; i++) delta[i] = (float)(0.4 * (random.NextDouble() - 0.5));
                QuaternionD decoded = OutputDecoder.Rotation(OutputDeltaMode.Slerp, q, delta);
                Assert.That(decoded.Length, Is.EqualTo(1).Within(1e-12));
                Assert.That(Quaternions.Dot(decoded, q), Is.GreaterThanOrEqualTo(0));
            }
        }

        [Test]
        public void GramSchmidtMatchesRotation6D()
        {
            double[] six = { 0.9, 0.3, -0.2, 0.1, 1.2, 0.4 };
            Matrix3x3D a = OutputDecoder.GramSchmidt(six[0], six[1], six[2], six[3], six[4], six[5]);
            Matrix3x3D b = Rotation6D.ToMatrix(six);
            for (int r = 0; r < 3; r++)
            {
                for (int col = 0; col < 3; col++) Assert.That(a[r, col], Is.EqualTo(b[r, col]).Within(1e-15));
            }
        }

        [Test]
        public void BaselineWeightsAreTheOfficialLinspace()
        {
            Assert.That(DeltaBaseline.Weight(0, 5), Is.EqualTo(1.0 / 6));
            Assert.That(DeltaBaseline.Weight(4, 5), Is.EqualTo(5.0 / 6));
            var last = new Vector3D(0, 1, 0);
            var target = new Vector3D(6, 1, 0);
            Assert.That(DeltaBaseline.RootPosition(OutputDeltaMode.Slerp, last, target, DeltaBaseline.Weight(2, 5)).X, Is.EqualTo(3).Within(1e-12));
            Assert.That(DeltaBaseline.RootPosition(OutputDeltaMode.LastPose, last, target, 0.5), Is.EqualTo(last));
            Assert.That(DeltaBaseline.RootPosition(OutputDeltaMode.None, last, target, 0.5), Is.EqualTo(Vector3D.Zero));
        }
    }
}
