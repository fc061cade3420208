using System;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Feet
{
    /// <summary>
    /// The run-time locker with the one contact source: a pose's predicted contacts (<see cref="LiveFootLocker.LockPose(double, ReadOnlySpan{double}, Span{double}, ReadOnlySpan{float}, double)"/>)
    /// decide touch-down and lift-off instead of the height and speed hysteresis. A generated walk pushed sideways
    /// between its start and target (its feet dragged along), shown at the walk's own 30 fps (each shown pose a frame of the walk).
    /// </summary>
    [TestFixture]
    public sealed class LiveFootContactsTests
    {
        private const double ClipFrameTime = 1.0 / 30, Fps = 30;

        /// <summary>Locks the dragged walk's poses with <paramref name="contacts"/> (time, channel → probability, or null: labelled) and returns the planted-foot slide before and after, and whether any predicted-free joint was held.</summary>
        private static (double Before, double After, bool HeldWhileFree) Run(int seed, Func<MotionClip, double, int, float>? contacts)
        {
            var random = new TestRandom(seed);
            Skeleton skeleton = FeetFixtures.LowerBody();
            var rig = FootRig.ForModel(skeleton);
            MotionClip walk = FeetFixtures.Walk(skeleton, 53, ClipFrameTime, random.Uniform(60, 100), random.Uniform(0.9, 1.2), 0, random.Uniform(0, 1));
            int j = skeleton.JointCount, start = 20, frames = (int)Math.Round(30 * ClipFrameTime * Fps);
            var locker = new LiveFootLocker(rig);
            double t0 = start * ClipFrameTime, t1 = t0 + 30 * ClipFrameTime;
            locker.Begin(walk.LocalPositions.AsSpan(walk.PositionIndex(start, 0), 3), walk.LocalRotations.AsSpan(walk.RotationIndex(start, 0), 4 * j),
                walk.LocalPositions.AsSpan(walk.PositionIndex(start + 30, 0), 3), walk.LocalRotations.AsSpan(walk.RotationIndex(start + 30, 0), 4 * j), t0, t1);
            var p = new float[4];
            double before = 0, after = 0;
            bool heldWhileFree = false;
            double[]? previousTruth = null, previousFilled = null, previousLocked = null;
            for (int r = 1; r < frames; r++)
            {
                double t = t0 + r / Fps;
                MotionClip truth = FeetFixtures.Copy(walk.Excerpt((int)Math.Round(t / ClipFrameTime), 1));
                MotionClip filled = FeetFixtures.Copy(truth);
                filled.LocalPositions[0] += 6 * Math.Sin(Math.PI * r / frames);
                MotionClip locked = FeetFixtures.Copy(filled);
                if (contacts != null)
                {
                    for (int c = 0; c < 4; c++) p[c] = contacts(walk, t, c);
                    locker.LockPose(t, locked.LocalPositions.AsSpan(0, 3), locked.LocalRotations.AsSpan(0, 4 * j), p, 0.5);
                    for (int c = 0; c < 4; c++) heldWhileFree |= p[c] < 0.5 && locker.IsPlanted(c);
                }
                else
                {
                    locker.LockPose(t, locked.LocalPositions.AsSpan(0, 3), locked.LocalRotations.AsSpan(0, 4 * j));
                }

                double[] gt = FeetFixtures.GlobalPositions(truth), gf = FeetFixtures.GlobalPositions(filled), gl = FeetFixtures.GlobalPositions(locked);
                if (previousTruth != null)
                {
                    foreach (int joint in rig.FootJoints)
                    {
                        if (Horizontal(gt, previousTruth!, joint) * Fps > 0.15 * rig.LegLength) continue;
                        before += Horizontal(gf, previousFilled!, joint);
                        after += Horizontal(gl, previousLocked!, joint);
                    }
                }

                (previousTruth, previousFilled, previousLocked) = (gt, gf, gl);
            }

            return (before, after, heldWhileFree);
        }

        [Test]
        public void AJointPredictedFreeIsNeverHeld([Range(0, 3)] int seed)
        {
            (_, _, bool heldWhileFree) = Run(seed, (walk, t, c) => 0.1f);
            Assert.That(heldWhileFree, Is.False);
        }

        [Test]
        public void TheTruthsContactsPredictedHoldItsPlantedFeet([Range(0, 3)] int seed)
        {
            // The walk's own contacts as the prediction: a joint planted while it moves slower than 15 % of a leg per second.
            (double before, double after, bool heldWhileFree) = Run(seed, TruthContacts);
            (_, double labelled, _) = Run(seed, null);
            TestContext.Out.WriteLine($"seed {seed}: slide {before:F2} unlocked, {after:F2} with the truth's contacts predicted, {labelled:F2} labelled");
            Assert.That(heldWhileFree, Is.False);
            // Measured 0.56–0.71 × unlocked (labelled: 0.08–0.16): contacts that start exactly where the truth's feet slow
            // down leave the ease-in of a foot's second joint on scored frames, and the labels plant earlier. The bound
            // guards that the predictions are used (without them nothing would be held); it is not issue 29's goal,
            // which FootLockFrameLoopTests and FootContactMeasureTests measure on real models.
            Assert.That(after, Is.LessThanOrEqualTo(0.75 * before));
        }

        [Test]
        public void ContactsThatAreNotFourProbabilitiesAreRefusedNamingTheArgument()
        {
            Skeleton skeleton = FeetFixtures.LowerBody();
            var locker = new LiveFootLocker(FootRig.ForModel(skeleton));
            MotionClip walk = FeetFixtures.Walk(skeleton, 10, ClipFrameTime, 80);
            int j = skeleton.JointCount;
            locker.Begin(walk.LocalPositions.AsSpan(0, 3), walk.LocalRotations.AsSpan(0, 4 * j), walk.LocalPositions.AsSpan(walk.PositionIndex(9, 0), 3), walk.LocalRotations.AsSpan(walk.RotationIndex(9, 0), 4 * j), 0, 0.3);
            var e = Assert.Throws<ArgumentException>(() => locker.LockPose(0.1, walk.LocalPositions.AsSpan(0, 3), walk.LocalRotations.AsSpan(0, 4 * j), new float[3], 0.5))!;
            Assert.That(e.ParamName, Is.EqualTo("contacts"));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => locker.LockPose(0.1, walk.LocalPositions.AsSpan(0, 3), walk.LocalRotations.AsSpan(0, 4 * j), new float[4], 1.5))!;
            Assert.That(e.ParamName, Is.EqualTo("threshold"));
        }

        private static float TruthContacts(MotionClip walk, double t, int channel)
        {
            var rig = FootRig.ForModel(walk.Skeleton);
            int joint = rig.FootJoints[channel];
            int f = (int)Math.Round(t / ClipFrameTime);
            double[] a = FeetFixtures.GlobalPositions(walk.Excerpt(f - 1, 1)), b = FeetFixtures.GlobalPositions(walk.Excerpt(f + 1, 1));
            return Horizontal(b, a, joint) / (2 * ClipFrameTime) < 0.15 * rig.LegLength ? 0.9f : 0.1f;
        }

        private static double Horizontal(double[] a, double[] b, int joint)
        {
            double dx = a[3 * joint] - b[3 * joint], dz = a[3 * joint + 2] - b[3 * joint + 2];
            return Math.Sqrt(dx * dx + dz * dz);
        }
    }
}
