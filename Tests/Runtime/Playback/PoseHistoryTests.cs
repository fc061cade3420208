using System;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Playback
{
    [TestFixture]
    public sealed class PoseHistoryTests
    {
        // A motion that SLERP/LERP between any two samples reproduces: the root moves at constant velocity,
        // every bone turns at constant angular velocity about a fixed axis. (SlerpPair takes normalised
        // linear weights for nearly equal rotations, hence 1e-5 rather than rounding error for rotations.)
        private static void Pose(double t, Span<double> root, Span<double> rotations)
        {
            new Vector3D(1.5 * t, 0.9, -0.5 * t).Write(root, 0);
            for (int b = 0; b < rotations.Length / 4; b++)
            {
                Quaternions.FromAxisAngle(Vector3D.UnitY, 0.3 + (b + 1) * 0.8 * t).Write(rotations, 4 * b);
            }
        }

        [TestCase(30.0)]
        [TestCase(144.0)]
        [TestCase(1000.0)]
        public void ResamplesTheGamesFramesAtTheModelsRate(double fps)
        {
            const int bones = 3;
            var history = new PoseHistory(bones, 30, 10);
            var random = new TestRandom(1);
            var root = new double[3];
            var rotations = new double[4 * bones];
            double t = 0;
            while (t < 2)
            {
                Pose(t, root, rotations);
                history.Record(t, root, rotations);
                t += (1 / fps) * (1 + 0.3 * random.Uniform(-1, 1));
            }

            double newest = history.NewestTime;
            var roots = new double[10 * 3];
            var resampled = new double[10 * 4 * bones];
            history.Resample(newest, 10, roots, resampled);
            for (int i = 0; i < 10; i++)
            {
                Pose(newest - (9 - i) / 30.0, root, rotations);
                RotationAssert.SameVector(Vector3D.Read(roots, 3 * i), Vector3D.Read(root, 0), 1e-9);
                for (int b = 0; b < bones; b++)
                {
                    RotationAssert.SameRotation(QuaternionD.Read(resampled, 4 * (i * bones + b)), QuaternionD.Read(rotations, 4 * b), 1e-5, $"frame {i} bone {b} at {fps} fps");
                }
            }

            // The newest sample is always the last pose recorded, however fast frames come.
            Pose(newest, root, rotations);
            var last = new double[4 * bones];
            var lastRoot = new double[3];
            history.Sample(newest + 1, lastRoot, last);
            Assert.That(last, Is.EqualTo(rotations));
            Assert.That(history.OldestTime, Is.LessThanOrEqualTo(newest - 9 / 30.0));
        }

        [Test]
        public void HoldsTheOldestBeforeItAndForgetsWhenTimeRestarts()
        {
            var history = new PoseHistory(1, 30, 10);
            var root = new double[3];
            var rotation = new double[4];
            Pose(1.0, root, rotation);
            history.Record(1.0, root, rotation);
            var sampledRoot = new double[3];
            var sampled = new double[4];
            history.Sample(0.0, sampledRoot, sampled);
            Assert.That(sampled, Is.EqualTo(rotation));
            Assert.That(sampledRoot, Is.EqualTo(root));

            Pose(0.5, root, rotation);
            history.Record(0.5, root, rotation);
            Assert.That(history.Count, Is.EqualTo(1));
            Assert.That(history.NewestTime, Is.EqualTo(0.5));
        }

        [Test]
        public void SamplingAnEmptyHistorySaysWhatToDo()
        {
            var history = new PoseHistory(1, 30, 10);
            var e = Assert.Throws<InvalidOperationException>(() => history.Sample(0, new double[3], new double[4]));
            Assert.That(e!.Message, Does.Contain("record at least one frame"));
        }
    }
}
