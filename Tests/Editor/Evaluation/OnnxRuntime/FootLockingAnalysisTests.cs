using System;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.Evaluation.Baking;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Where a bake's foot skating after locking comes from. Three LaFAN1 files of its training subjects (chosen
    /// for walking, turning and obstacles; never the benchmark's subject 5 or a held-out CMU subject) are baked
    /// with the shipped default model and SLERP at keys every 15 and 30 frames, and each filled clip is locked
    /// twice: with the contacts <see cref="FootLocker"/> labels from the keys and the filled motion (what
    /// <c>bake --feet lock</c> does), and with the truth's own contacts (the measure's rule,
    /// <see cref="FootSkating.Planted(System.ReadOnlySpan{double}, int, double, double, double)"/>), which no bake knows. The second separates what locking reaches when
    /// contacts are known from what labelling them loses; every skating sample (a truth-planted foot joint on a
    /// filled frame) is also split by the locker's state there: held, held but out of the leg's reach, easing in,
    /// easing out, or free. Prints the table; asserts the ordering the analysis rests on.
    /// </summary>
    [TestFixture]
    public sealed class FootLockingAnalysisTests
    {
        private static readonly string[] Files = { "walk4_subject1", "obstacles1_subject1", "ground1_subject1" };
        private static readonly string[] States = { "held", "out of reach", "easing in", "easing out", "free" };

        [TestCase(15)]
        [TestCase(30)]
        public void LockingWithTheTruthsContactsSkatesLessThanWithLabelledOnesAndBothLessThanNone(int every)
        {
            string lafan = TestEnvironment.RequireLafan1();
            string modelPath = ShippedModelTests.RequireDefaultModel();
            if (!File.Exists(modelPath)) Assert.Ignore($"{modelPath} not found; skipping.");
            using Inbetweener model = OnnxRuntimeInbetweener.Load(modelPath);
            var totals = new Totals[2];
            double truthSum = 0;
            int truthSamples = 0;
            foreach (string name in Files)
            {
                string file = Path.Combine(lafan, name + ".bvh");
                if (!File.Exists(file)) Assert.Ignore($"{file} not found; skipping.");
                MotionClip truth = BvhReader.Read(file).Motion;
                int[] keys = BakeKeys.Every(every, truth, 0, model.Contract);
                BakeRun run = InbetweenBake.Run(truth, keys, RigRetargeting.For(model.Contract, truth, file, null, null), new[] { BakeMethod.Model(model), BakeMethod.Slerp() });
                FootRig feet = FootRig.ForModel(truth.Skeleton);
                FootSkating floor = FootSkating.OfTruth(truth, keys, feet);
                truthSum += floor.MeanSpeed * floor.ContactSamples;
                truthSamples += floor.ContactSamples;
                for (int m = 0; m < 2; m++)
                {
                    totals[m] ??= new Totals();
                    FootLockSettings settings = m == 0 ? new FootLockSettings() : FootLockSettings.ForInterpolation();
                    Analyse(truth, run.Methods[m].OnRig, keys, feet, settings, totals[m]);
                }
            }

            double floorSpeed = truthSum / truthSamples;
            TestContext.Out.WriteLine($"keys every {every} frames, {Files.Length} LaFAN1 files, truth's own skating {floorSpeed:F3} leg lengths/s:");
            for (int m = 0; m < 2; m++)
            {
                Totals t = totals[m];
                string method = m == 0 ? "model" : "SLERP";
                double off = t.Off / t.Samples, labelled = t.Labelled / t.Samples, known = t.Known / t.Samples;
                TestContext.Out.WriteLine($"  {method}: off {off:F3}; locked {labelled:F3} (× {labelled / off:F2} off, × {labelled / floorSpeed:F1} truth); " +
                    $"locked with the truth's contacts {known:F3} (× {known / off:F2} off, × {known / floorSpeed:F1} truth)");
                for (int k = 0; k < 2; k++)
                {
                    double[] sum = k == 0 ? t.LabelledByState : t.KnownByState;
                    int[] count = k == 0 ? t.LabelledCount : t.KnownCount;
                    string line = k == 0 ? "    labelled:" : "    truth's: ";
                    double all = k == 0 ? t.Labelled : t.Known;
                    for (int s = 0; s < States.Length; s++) line += $" {States[s]} {100.0 * count[s] / t.Samples:F0} % of samples, {100 * sum[s] / all:F0} % of skating;";
                    TestContext.Out.WriteLine(line);
                }

                Assert.That(t.Samples, Is.GreaterThan(1000), $"{method}: truth-planted samples");
                Assert.That(known, Is.LessThan(labelled), $"{method}: locked with the truth's contacts vs with labelled contacts");
                Assert.That(labelled, Is.LessThan(off), $"{method}: locked with labelled contacts vs not locked");
            }
        }

        /// <summary>Locks a copy of <paramref name="filled"/> with labelled and with the truth's contacts and adds every truth-planted sample's speeds.</summary>
        private static void Analyse(MotionClip truth, MotionClip filled, int[] keys, FootRig feet, FootLockSettings settings, Totals totals)
        {
            int frames = filled.FrameCount, first = keys[0];
            var relative = new int[keys.Length];
            for (int i = 0; i < keys.Length; i++) relative[i] = keys[i] - first;
            var isKey = new bool[frames];
            foreach (int k in relative) isKey[k] = true;

            var footJoints = feet.FootJoints;
            int n = footJoints.Count;
            Assert.That(n, Is.EqualTo(FootLocker.ChannelCount), "the model's rig has a toe on each foot: foot joints are the locker's channels");
            double[] truthFeet = FootSkating.FootPositions(truth, first, frames, footJoints);
            double ground = FootSkating.GroundLevel(truthFeet, n);
            bool[] planted = FootSkating.Planted(truthFeet, n, truth.FrameTime, ground, feet.LegLength);
            double[] offFeet = FootSkating.FootPositions(filled, 0, frames, footJoints);

            var labelled = new FootLocker(feet, settings);
            MotionClip labelledClip = Copy(filled);
            labelled.Lock(labelledClip, relative);
            double[] labelledFeet = FootSkating.FootPositions(labelledClip, 0, frames, footJoints);
            var known = new FootLocker(feet, settings);
            MotionClip knownClip = Copy(filled);
            known.LockWithContacts(knownClip, relative, planted);
            double[] knownFeet = FootSkating.FootPositions(knownClip, 0, frames, footJoints);

            double dt = truth.FrameTime, leg = feet.LegLength, limit = ground + FootSkating.ContactHeight * leg;
            for (int f = 1; f + 1 < frames; f++)
            {
                if (isKey[f]) continue;
                for (int c = 0; c < n; c++)
                {
                    // The measure's own samples (FootSkating.Accumulate): truth within the contact height, slower than the contact speed.
                    if (truthFeet[(f * n + c) * 3 + 1] > limit || Speed(truthFeet, f, c, n, dt) >= FootSkating.ContactSpeed * leg) continue;
                    totals.Samples++;
                    totals.Off += Speed(offFeet, f, c, n, dt) / leg;
                    double a = Speed(labelledFeet, f, c, n, dt) / leg, b = Speed(knownFeet, f, c, n, dt) / leg;
                    totals.Labelled += a;
                    totals.Known += b;
                    int sa = State(labelled, f, c), sb = State(known, f, c);
                    totals.LabelledByState[sa] += a;
                    totals.LabelledCount[sa]++;
                    totals.KnownByState[sb] += b;
                    totals.KnownCount[sb]++;
                }
            }
        }

        private static int State(FootLocker locker, int f, int c)
        {
            double w = locker.LockWeight(f, c);
            if (w >= 1) return locker.IsPlanted(f, c) ? 0 : 1;
            if (w <= 0) return 4;
            return locker.LockWeight(f + 1, c) > w ? 2 : 3;
        }

        private static double Speed(double[] feet, int f, int c, int n, double dt)
        {
            int a = ((f + 1) * n + c) * 3, b = ((f - 1) * n + c) * 3;
            double dx = feet[a] - feet[b], dz = feet[a + 2] - feet[b + 2];
            return Math.Sqrt(dx * dx + dz * dz) / (2 * dt);
        }

        private static MotionClip Copy(MotionClip clip) =>
            new MotionClip(clip.Skeleton, clip.FrameCount, clip.FrameTime, (double[])clip.LocalPositions.Clone(), (double[])clip.LocalRotations.Clone());

        private sealed class Totals
        {
            public int Samples;
            public double Off, Labelled, Known;
            public readonly double[] LabelledByState = new double[States.Length], KnownByState = new double[States.Length];
            public readonly int[] LabelledCount = new int[States.Length], KnownCount = new int[States.Length];
        }
    }
}
