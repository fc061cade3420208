using System;
using System.IO;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Feet
{
    /// <summary>
    /// The one contact source (<see cref="FootContacts"/>): where a model predicted contacts they decide which foot joints
    /// the bake's locker plants; where it did not (keys, SLERP, models without the output) the locker labels them as
    /// before, bit for bit.
    /// </summary>
    [TestFixture]
    public sealed class FootContactsTests
    {
        private const double FrameTime = 1.0 / 30;

        private static (MotionClip Filled, int[] Keys, FootRig Rig) SlerpWalk(int seed)
        {
            var random = new TestRandom(seed);
            Skeleton skeleton = FeetFixtures.LowerBody();
            MotionClip truth = FeetFixtures.Walk(skeleton, 121, FrameTime, random.Uniform(60, 100), random.Uniform(0.9, 1.2));
            int[] keys = KeyFrames.Every(30, truth.FrameCount);
            var baker = new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline());
            return (baker.Bake(truth, baker.Plan(truth.FrameCount, keys)), keys, FootRig.ForModel(skeleton));
        }

        [Test]
        public void WithoutPredictionsTheLockerLabelsAsBefore([Range(0, 3)] int seed)
        {
            (MotionClip filled, int[] keys, FootRig rig) = SlerpWalk(seed);
            MotionClip labelled = FeetFixtures.Copy(filled), sourced = FeetFixtures.Copy(filled);
            new FootLocker(rig).Lock(labelled, keys);
            var contacts = new FootContacts();
            contacts.Clear(filled.FrameCount);
            new FootLocker(rig).Lock(sourced, keys, contacts);
            Assert.That(contacts.AnyPredicted, Is.False);
            Assert.That(sourced.LocalRotations, Is.EqualTo(labelled.LocalRotations), "no prediction: the labelled contacts, bit for bit");
        }

        [Test]
        public void PredictedContactsDecideEveryPredictedFrame([Range(0, 3)] int seed)
        {
            (MotionClip filled, int[] keys, FootRig rig) = SlerpWalk(seed);
            int frames = filled.FrameCount;
            var isKey = new bool[frames];
            foreach (int k in keys) isKey[k] = true;
            // A prediction unlike any label: each joint planted for 8 frames, then free for 7, out of phase per channel.
            var p = new float[frames * FootContacts.ChannelCount];
            for (int f = 0; f < frames; f++)
            {
                for (int c = 0; c < FootContacts.ChannelCount; c++) p[f * 4 + c] = (f + 4 * c) % 15 < 8 ? 0.9f : 0.1f;
            }

            var contacts = new FootContacts();
            contacts.Clear(frames);
            for (int f = 0; f < frames; f++)
            {
                if (!isKey[f]) contacts.SetPredicted(f, 1, p.AsSpan(f * 4, 4), 0.5);
            }

            var locker = new FootLocker(rig);
            locker.Plan(filled, keys, contacts);
            int predictedPlanted = 0, held = 0;
            for (int f = 0; f < frames; f++)
            {
                if (isKey[f]) continue;
                Assert.That(contacts.IsPredicted(f), Is.True);
                for (int c = 0; c < FootContacts.ChannelCount; c++)
                {
                    if (!contacts.IsPlanted(f, c))
                    {
                        Assert.That(locker.IsPlanted(f, c), Is.False, $"frame {f} channel {c}: predicted free");
                        continue;
                    }

                    predictedPlanted++;
                    if (locker.IsPlanted(f, c)) held++;
                }
            }

            TestContext.Out.WriteLine($"seed {seed}: {held} of {predictedPlanted} predicted planted samples held");
            // The rest are frames the leg cannot reach, or trimmed to ease from one contact to the next.
            Assert.That(held, Is.GreaterThan(0.75 * predictedPlanted));
        }

        [Test]
        public void ContactsFollowTimeOntoAnotherFrameRate()
        {
            var contacts = new FootContacts();
            contacts.Clear(4);
            contacts.SetPredicted(1, 2, new float[] { 0.9f, 0.1f, 0.9f, 0.1f, 0.2f, 0.8f, 0.2f, 0.8f }, 0.4);
            var rig = new FootContacts();
            contacts.ResampleInto(rig, 8, FrameTime / 2, FrameTime, 0);
            Assert.That(rig.Threshold, Is.EqualTo(0.4));
            // 60 fps frame f is at 30 fps frame f / 2 (rounded half to even): 0 0 1 2 2 2 3 4→none.
            bool[] predicted = { false, false, true, true, true, true, false, false };
            for (int f = 0; f < 8; f++) Assert.That(rig.IsPredicted(f), Is.EqualTo(predicted[f]), $"frame {f}");
            Assert.That(rig.IsPlanted(2, 0), Is.True);
            Assert.That(rig.IsPlanted(3, 0), Is.False);
            Assert.That(rig.IsPlanted(3, 1), Is.True);
        }

        [Test]
        public void BadPredictionsAreRefusedNamingTheArgument()
        {
            var contacts = new FootContacts();
            contacts.Clear(10);
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => contacts.SetPredicted(8, 3, new float[12], 0.5))!;
            Assert.That(e.ParamName, Is.EqualTo("frame"));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => contacts.SetPredicted(0, 1, new float[4], 1.0))!;
            Assert.That(e.ParamName, Is.EqualTo("threshold"));
            (MotionClip filled, int[] keys, FootRig rig) = SlerpWalk(0);
            var a = Assert.Throws<ArgumentException>(() => new FootLocker(rig).Lock(FeetFixtures.Copy(filled), keys, contacts))!;
            Assert.That(a.ParamName, Is.EqualTo("predicted"));
        }
    }
}
