using System;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Blends
{
    /// <summary>
    /// Issue 28, transform offsets: the step that puts a character on the track's placement in one frame
    /// (<see cref="RootVelocity"/>), and Timeline's offsets and a transform read as placements on the ground.
    /// </summary>
    [TestFixture]
    public sealed class RootVelocityTests
    {
        private static double Distance(RootPlacement a, RootPlacement b) =>
            Math.Max(Math.Max(Math.Abs(a.X - b.X), Math.Abs(a.Z - b.Z)), Math.Abs(Math.IEEERemainder(a.Yaw - b.Yaw, 2 * Math.PI)));

        // As the engine applies root motion (the convention the spans' travel already uses): the step in the character's frame, then the turn.
        private static RootPlacement Applied(RootPlacement current, double x, double z, double yawRate, double dt) =>
            current.Then(new RootPlacement(x * dt, z * dt, yawRate * dt));

        [Test]
        public void TheVelocityPutsTheCharacterExactlyOnTheTargetInOneFrameFacingAnyWay()
        {
            var random = new Random(28);
            double worst = 0;
            for (int i = 0; i < 1000; i++)
            {
                var current = new RootPlacement(random.NextDouble() * 40 - 20, random.NextDouble() * 40 - 20, random.NextDouble() * 20 - 10);
                var target = new RootPlacement(random.NextDouble() * 40 - 20, random.NextDouble() * 40 - 20, random.NextDouble() * 20 - 10);
                double dt = 1.0 / (10 + random.NextDouble() * 200);
                RootVelocity.Toward(current, target, dt, out double x, out double z, out double yawRate);
                worst = Math.Max(worst, Distance(Applied(current, x, z, yawRate, dt), target));
                Assert.That(Math.Abs(yawRate * dt), Is.LessThanOrEqualTo(Math.PI + 1e-12), "the shorter way round");
            }

            TestContext.WriteLine($"1000 random frames: largest distance from the target after one frame {worst:E2}");
            Assert.That(worst, Is.LessThan(1e-9));
        }

        [Test]
        public void AFrameOfNoLengthMovesNothingAndAPlacementThatIsNoNumberIsRefused()
        {
            var current = new RootPlacement(1, 2, 0.3);
            var target = new RootPlacement(4, -2, 1.3);
            foreach (double dt in new[] { 0.0, -0.1, double.NaN, double.PositiveInfinity })
            {
                RootVelocity.Toward(current, target, dt, out double x, out double z, out double yawRate);
                Assert.That((x, z, yawRate), Is.EqualTo((0.0, 0.0, 0.0)), $"dt {dt}");
            }

            var e = Assert.Throws<ArgumentOutOfRangeException>(() => RootVelocity.Toward(new RootPlacement(double.NaN, 0, 0), target, 0.1, out _, out _, out _));
            Assert.That(e!.ParamName, Is.EqualTo("current"));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => RootVelocity.Toward(current, new RootPlacement(0, double.PositiveInfinity, 0), 0.1, out _, out _, out _));
            Assert.That(e!.ParamName, Is.EqualTo("target"));
        }

        [Test]
        public void AFacingAWholeTurnAwayIsTheSameFacing()
        {
            RootVelocity.Toward(new RootPlacement(0, 0, 0.1), new RootPlacement(0, 0, 0.1 + 4 * Math.PI), 1.0 / 60, out double x, out double z, out double yawRate);
            Assert.That((x, z), Is.EqualTo((0.0, 0.0)));
            Assert.That(Math.Abs(yawRate), Is.LessThan(1e-9));
        }

        [Test]
        public void TimelinesOffsetsArePlacementsOnTheGroundAndWhatIsNotIsSaid()
        {
            // Quaternion.Euler(0, 90, 0) turns +Z to +X: yaw π/2 in RootPlacement's convention.
            RootPlacement offset = RootPlacement.OfOffset(2, 0, 3, 0, 90, 0, out bool flattened);
            Assert.That(Distance(offset, new RootPlacement(2, 3, Math.PI / 2)), Is.LessThan(1e-15));
            Assert.That(flattened, Is.False);
            Assert.That(Distance(offset.Then(new RootPlacement(0, 1, 0)), new RootPlacement(3, 3, Math.PI / 2)), Is.LessThan(1e-15), "a step ahead goes along +X");

            RootPlacement.OfOffset(2, 0.5, 3, 0, 90, 0, out flattened);
            Assert.That(flattened, Is.True, "a height");
            RootPlacement pitched = RootPlacement.OfOffset(0, 0, 0, 30, 40, 0, out flattened);
            Assert.That(flattened, Is.True, "a pitch");
            Assert.That(pitched.Yaw, Is.EqualTo(40 * Math.PI / 180).Within(1e-15), "a pitch under 90° does not change where it faces");
            RootPlacement rolled = RootPlacement.OfOffset(0, 0, 0, 0, -20, 15, out flattened);
            Assert.That(flattened, Is.True, "a roll");
            Assert.That(rolled.Yaw, Is.EqualTo(-20 * Math.PI / 180).Within(1e-15));
            RootPlacement over = RootPlacement.OfOffset(0, 0, 0, 180, 0, 0, out _);
            Assert.That(Math.Abs(Math.IEEERemainder(over.Yaw - Math.PI, 2 * Math.PI)), Is.LessThan(1e-12), "pitched over: it faces back");
            RootPlacement.OfOffset(0, 0, 0, 360, 0, -360, out flattened);
            Assert.That(flattened, Is.False, "whole turns are no pitch or roll");
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => RootPlacement.OfOffset(0, 0, 0, 0, double.NaN, 0, out _));
            Assert.That(e!.ParamName, Is.EqualTo("yaw"));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => RootPlacement.OfOffset(double.PositiveInfinity, 0, 0, 0, 0, 0, out _));
            Assert.That(e!.ParamName, Is.EqualTo("x"));
        }

        [Test]
        public void ATransformsPlacementIsItsGroundPositionAndFacing()
        {
            double h = 35 * Math.PI / 180;
            // A turn of 70° about +Y (w, x, y, z).
            RootPlacement turned = RootPlacement.OfTransform(1.5, -2, new QuaternionD(Math.Cos(h), 0, Math.Sin(h), 0));
            Assert.That(Distance(turned, new RootPlacement(1.5, -2, 70 * Math.PI / 180)), Is.LessThan(1e-15));
            // Tilted 20° about its own +X after the turn: it still faces 70°.
            double t = 10 * Math.PI / 180;
            QuaternionD tilted = Quaternions.Multiply(new QuaternionD(Math.Cos(h), 0, Math.Sin(h), 0), new QuaternionD(Math.Cos(t), Math.Sin(t), 0, 0));
            Assert.That(RootPlacement.OfTransform(0, 0, tilted).Yaw, Is.EqualTo(70 * Math.PI / 180).Within(1e-12));
        }

        [Test]
        public void ARotationTurnedToAFacingFacesItAndKeepsItsPitchAndRoll()
        {
            var random = new Random(2801);
            double worstFacing = 0, worstTilt = 0;
            for (int i = 0; i < 1000; i++)
            {
                // A character's rotation with some pitch and roll (under 60°, so it does not face straight up or down).
                QuaternionD tilt = Quaternions.Multiply(
                    new QuaternionD(Math.Cos(random.NextDouble() * 0.5 - 0.25), Math.Sin(random.NextDouble() * 0.5 - 0.25), 0, 0),
                    new QuaternionD(Math.Cos(random.NextDouble() * 0.5 - 0.25), 0, 0, Math.Sin(random.NextDouble() * 0.5 - 0.25)));
                double from = random.NextDouble() * 20 - 10, yaw = random.NextDouble() * 20 - 10;
                QuaternionD rotation = Quaternions.Multiply(new QuaternionD(Math.Cos(from / 2), 0, Math.Sin(from / 2), 0), Quaternions.Normalize(tilt));
                QuaternionD turned = RootPlacement.TurnedTo(rotation, yaw);
                worstFacing = Math.Max(worstFacing, Math.Abs(Math.IEEERemainder(RootPlacement.OfTransform(0, 0, turned).Yaw - yaw, 2 * Math.PI)));
                // Pitch and roll kept: the rotation relative to its own facing is the same before and after.
                QuaternionD before = Quaternions.Multiply(Yaw(-RootPlacement.OfTransform(0, 0, rotation).Yaw), rotation);
                QuaternionD after = Quaternions.Multiply(Yaw(-yaw), turned);
                worstTilt = Math.Max(worstTilt, 1 - Math.Abs(before.W * after.W + before.X * after.X + before.Y * after.Y + before.Z * after.Z));
            }

            Assert.That(worstFacing, Is.LessThan(1e-9), "facing reached");
            Assert.That(worstTilt, Is.LessThan(1e-12), "pitch and roll kept");
        }

        private static QuaternionD Yaw(double angle) => new QuaternionD(Math.Cos(angle / 2), 0, Math.Sin(angle / 2), 0);
    }
}
