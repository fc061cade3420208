using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Baking
{
    /// <summary>
    /// <see cref="ClipBaker"/> on synthetic motion: keys copied exactly, gaps filled in order with the
    /// context the baker documents (keys and filled frames, padded or not under the short-context policy),
    /// SLERP baking equal to <see cref="SlerpBaseline"/> gap by gap, refusals and warnings.
    /// </summary>
    public sealed class ClipBakerTests
    {
        private static readonly Skeleton ThreeJoints = new Skeleton(
            new[] { "root", "spine", "head" }, new[] { -1, 0, 1 }, new double[] { 0, 0, 0, 0, 10, 0, 0, 8, 1 });

        /// <summary>A clip of random poses (no two frames alike), every joint with its offset as local translation.</summary>
        internal static MotionClip RandomClip(int frames, int seed)
        {
            var random = new TestRandom(seed);
            MotionClip clip = MotionClip.CreateRestPose(ThreeJoints, frames, 1.0 / 30);
            for (int f = 0; f < frames; f++)
            {
                random.Vector(50).Write(clip.LocalPositions, clip.PositionIndex(f, 0));
                for (int j = 0; j < 3; j++) random.Rotation().Write(clip.LocalRotations, clip.RotationIndex(f, j));
            }

            return clip;
        }

        [Test]
        public void SlerpBakeKeepsKeysExactlyAndEqualsSlerpBaselinePerGap()
        {
            MotionClip source = RandomClip(30, 1);
            int[] keys = { 2, 7, 8, 19, 27 };
            var baker = new ClipBaker(new SlerpBaseline(), BakeSettings.ForBaseline());
            BakePlan plan = baker.Plan(source.FrameCount, keys);
            MotionClip baked = baker.Bake(source, plan);

            Assert.That(baked.FrameCount, Is.EqualTo(26), "frames 2..27");
            Assert.That(plan.Gaps.Count, Is.EqualTo(3), "7→8 has no missing frame");
            foreach (int key in keys) AssertSameFrame(baked, key - 2, source, key);

            for (int i = 0; i + 1 < keys.Length; i++)
            {
                int n = keys[i + 1] - keys[i] - 1;
                if (n == 0) continue;
                var t = new Transition(ThreeJoints, 1, n);
                PastContext.FillPast(t, RootOf(source), source.LocalRotations, keys[i], 1);
                PastContext.FillTarget(t, RootOf(source), source.LocalRotations, keys[i + 1]);
                new SlerpBaseline().Inbetween(t);
                for (int k = 0; k < n; k++)
                {
                    int f = keys[i] + 1 + k - 2;
                    for (int c = 0; c < 3; c++) Assert.That(baked.LocalPositions[baked.PositionIndex(f, 0) + c], Is.EqualTo(t.RootPositions[3 * k + c]));
                    for (int c = 0; c < 12; c++) Assert.That(baked.LocalRotations[baked.RotationIndex(f, 0) + c], Is.EqualTo(t.LocalRotations[12 * k + c]));
                    for (int c = 3; c < 9; c++) Assert.That(baked.LocalPositions[baked.PositionIndex(f, 0) + c], Is.EqualTo(ThreeJoints.Offsets[c]), "non-root joints at their offsets");
                }
            }
        }

        [Test]
        public void FillsGapsInOrderWithKeysAndFilledFramesAsContext()
        {
            MotionClip source = RandomClip(40, 2);
            int[] keys = { 0, 6, 20, 39 };
            var recorder = new RecordingInbetweener();
            var settings = new BakeSettings { PastFrames = 4, ShortContext = ShortContextPolicy.FeedAvailable };
            var baker = new ClipBaker(recorder, settings);
            MotionClip baked = baker.Bake(source, baker.Plan(source.FrameCount, keys));

            Assert.That(recorder.Calls.Count, Is.EqualTo(3));
            for (int i = 0; i < 3; i++)
            {
                Call call = recorder.Calls[i];
                Assert.That(call.Missing, Is.EqualTo(keys[i + 1] - keys[i] - 1), $"gap {i} filled in order");
                Assert.That(call.PastFrames, Is.EqualTo(i == 0 ? 1 : 4), "first gap: only the first key exists (fed alone); later: 4 frames");
                // The past keys are the baked clip's frames ending at the key before the gap — key frames
                // and frames filled by earlier gaps alike — and the target is the next key.
                for (int p = 0; p < call.PastFrames; p++)
                {
                    int frame = keys[i] - call.PastFrames + 1 + p;
                    for (int c = 0; c < 3; c++) Assert.That(call.KeyRoot[3 * p + c], Is.EqualTo(baked.LocalPositions[baked.PositionIndex(frame, 0) + c]));
                    for (int c = 0; c < 12; c++) Assert.That(call.KeyRotations[12 * p + c], Is.EqualTo(baked.LocalRotations[baked.RotationIndex(frame, 0) + c]));
                }

                for (int c = 0; c < 12; c++) Assert.That(call.KeyRotations[12 * call.PastFrames + c], Is.EqualTo(source.LocalRotations[source.RotationIndex(keys[i + 1], 0) + c]));
            }

            // Gap 2's context (frames 17..20) holds frames 17..19 filled by gap 1, not the source's.
            Assert.That(recorder.Calls[2].KeyRotations[0], Is.Not.EqualTo(source.LocalRotations[source.RotationIndex(17, 0)]));
            foreach (int key in keys) AssertSameFrame(baked, key, source, key);
        }

        [Test]
        public void WithoutFilledFramesOnlyConsecutiveKeysAreContext()
        {
            MotionClip source = RandomClip(30, 4);
            int[] keys = { 0, 1, 2, 10, 20 };
            var recorder = new RecordingInbetweener();
            var settings = new BakeSettings { PastFrames = 4, ShortContext = ShortContextPolicy.FeedAvailable, FilledFramesAsContext = false };
            var baker = new ClipBaker(recorder, settings);
            BakePlan plan = baker.Plan(source.FrameCount, keys);
            Assert.That(plan.Gaps.Count, Is.EqualTo(2));
            Assert.That(plan.Gaps[0].PastAvailable, Is.EqualTo(3), "keys 0, 1, 2");
            Assert.That(plan.Gaps[1].PastAvailable, Is.EqualTo(1), "key 10 alone: frames 7..9 were filled");
            baker.Bake(source, plan);
            Call second = recorder.Calls[1];
            Assert.That(second.PastFrames, Is.EqualTo(1));
            for (int c = 0; c < 12; c++) Assert.That(second.KeyRotations[c], Is.EqualTo(source.LocalRotations[source.RotationIndex(10, 0) + c]));

            settings.FilledFramesAsContext = true;
            Assert.That(baker.Plan(source.FrameCount, keys).Gaps[1].PastAvailable, Is.EqualTo(4), "with filled frames: 7..10");
        }

        [Test]
        public void RepeatEarliestPadsTheFirstGapsToTheWantedPastFrames()
        {
            MotionClip source = RandomClip(30, 3);
            int[] keys = { 0, 3, 12, 29 };
            var recorder = new RecordingInbetweener();
            var baker = new ClipBaker(recorder, new BakeSettings { PastFrames = 10, ShortContext = ShortContextPolicy.RepeatEarliest });
            BakePlan plan = baker.Plan(source.FrameCount, keys);
            Assert.That(plan.Gaps[0].PastAvailable, Is.EqualTo(1));
            Assert.That(plan.Gaps[1].PastAvailable, Is.EqualTo(4));
            Assert.That(plan.Gaps[2].PastAvailable, Is.EqualTo(10));
            MotionClip baked = baker.Bake(source, plan);

            foreach (Call call in recorder.Calls) Assert.That(call.PastFrames, Is.EqualTo(10));
            // Gap 1: frames 0..3 exist; keys 0..6 repeat frame 0, keys 6..9 are frames 0..3.
            Call second = recorder.Calls[1];
            for (int p = 0; p < 10; p++)
            {
                int frame = p < 6 ? 0 : p - 6;
                for (int c = 0; c < 12; c++) Assert.That(second.KeyRotations[12 * p + c], Is.EqualTo(baked.LocalRotations[baked.RotationIndex(frame, 0) + c]));
            }
        }

        [Test]
        public void RefusesWhatCannotBeBaked()
        {
            var baker = new ClipBaker(new SlerpBaseline(), new BakeSettings { MaxFrameIndex = 20, Name = "m" });
            Assert.That(() => baker.Plan(30, new[] { 4 }), Throws.TypeOf<KeyLayoutException>().With.Message.Contains("at least two keys"));
            Assert.That(() => baker.Plan(30, new[] { 0, 30 }), Throws.TypeOf<KeyLayoutException>().With.Message.Contains("key 30 is outside the clip's frames 0..29"));
            Assert.That(() => baker.Plan(30, new[] { -1, 5 }), Throws.TypeOf<KeyLayoutException>().With.Message.Contains("outside"));
            Assert.That(() => baker.Plan(30, new[] { 0, 12, 5 }), Throws.TypeOf<KeyLayoutException>().With.Message.Contains("key 5 comes after key 12"));
            Assert.That(() => baker.Plan(30, new[] { 0, 5, 5, 9 }), Throws.TypeOf<KeyLayoutException>().With.Message.Contains("key 5 is given twice"));
            // 1 past key + 19 missing → the target at index 20: the most the graph takes; 20 missing is refused.
            Assert.That(() => baker.Plan(30, new[] { 0, 21 }), Throws.TypeOf<KeyLayoutException>().With.Message.Contains("keys 0 and 21 has 20 missing frames"));
            BakePlan fits = baker.Plan(30, new[] { 0, 20 });
            Assert.That(fits.Gaps[0].PastFrames, Is.EqualTo(1));
        }

        [Test]
        public void FeedsFewerPastKeysWhenTheGapFitsOnlySoAndWarnsOutsideTrainedRanges()
        {
            var settings = new BakeSettings
            {
                PastFrames = 10,
                ShortContext = ShortContextPolicy.RepeatEarliest,
                MaxFrameIndex = 40,
                TrainedPastFrames = (10, 10),
                TrainedMissingFrames = (5, 30),
                Name = "m",
            };
            var baker = new ClipBaker(new SlerpBaseline(), settings);
            BakePlan plan = baker.Plan(100, new[] { 0, 20, 22, 57, 90 });
            Assert.That(plan.Gaps[2].MissingFrames, Is.EqualTo(34));
            Assert.That(plan.Gaps[2].PastFrames, Is.EqualTo(6), "40 − 34: fewer past keys so that the target index stays ≤ 40");
            Assert.That(plan.Gaps[3].PastFrames, Is.EqualTo(8), "40 − 32");
            Assert.That(plan.Gaps[0].PastFrames, Is.EqualTo(10), "the first gap repeats the first key to 10");
            Assert.That(plan.Warnings, Has.Some.Contains("gaps are longer than the 30").And.Contains("keys 22–57 (34 missing)"));
            Assert.That(plan.Warnings, Has.Some.Contains("1 gap is shorter than the 5").And.Contains("keys 20–22 (1 missing). Baked anyway."));
            Assert.That(plan.Warnings, Has.Some.Contains("Fed with fewer past keys."));
            Assert.That(plan.Warnings, Has.Some.Contains("fed a number of past keys outside the 10..10"));
        }

        [Test]
        public void ShortContextPolicyFollowsTheTrainedPastRange()
        {
            Assert.That(BakeSettings.ChooseShortContext((10, 10)), Is.EqualTo(ShortContextPolicy.RepeatEarliest), "trained at 10 only");
            Assert.That(BakeSettings.ChooseShortContext((1, 10)), Is.EqualTo(ShortContextPolicy.FeedAvailable), "trained on 1..10");
            Assert.That(BakeSettings.ChooseShortContext((5, 10)), Is.EqualTo(ShortContextPolicy.RepeatEarliest), "a single key was never seen");
            Assert.That(BakeSettings.ChooseShortContext((0, 0)), Is.EqualTo(ShortContextPolicy.RepeatEarliest), "unknown range: the benchmark layout");
        }

        [Test]
        public void KeysEveryKEndOnTheLastFrame()
        {
            Assert.That(KeyFrames.Every(15, 31), Is.EqualTo(new[] { 0, 15, 30 }));
            Assert.That(KeyFrames.Every(15, 35), Is.EqualTo(new[] { 0, 15, 30, 34 }));
            Assert.That(() => KeyFrames.Every(0, 35), Throws.TypeOf<KeyLayoutException>());
        }

        private static double[] RootOf(MotionClip clip)
        {
            var root = new double[clip.FrameCount * 3];
            for (int f = 0; f < clip.FrameCount; f++) Array.Copy(clip.LocalPositions, clip.PositionIndex(f, 0), root, 3 * f, 3);
            return root;
        }

        public static void AssertSameFrame(MotionClip baked, int bakedFrame, MotionClip source, int sourceFrame)
        {
            int j = source.Skeleton.JointCount;
            for (int c = 0; c < 3 * j; c++)
            {
                Assert.That(baked.LocalPositions[baked.PositionIndex(bakedFrame, 0) + c], Is.EqualTo(source.LocalPositions[source.PositionIndex(sourceFrame, 0) + c]), $"key {sourceFrame} position");
            }

            for (int c = 0; c < 4 * j; c++)
            {
                Assert.That(baked.LocalRotations[baked.RotationIndex(bakedFrame, 0) + c], Is.EqualTo(source.LocalRotations[source.RotationIndex(sourceFrame, 0) + c]), $"key {sourceFrame} rotation");
            }
        }

        private sealed class Call
        {
            public int PastFrames;
            public int Missing;
            public double[] KeyRoot = Array.Empty<double>();
            public double[] KeyRotations = Array.Empty<double>();
        }

        /// <summary>SLERP that also records the key frames of every request it gets (to check what the baker feeds).</summary>
        private sealed class RecordingInbetweener : IInbetweener
        {
            private readonly SlerpBaseline _slerp = new SlerpBaseline();

            public List<Call> Calls { get; } = new List<Call>();

            public string Id => "recording";

            public string DisplayName => "Recording SLERP";

            public void Inbetween(Transition transition)
            {
                Calls.Add(new Call
                {
                    PastFrames = transition.PastFrames,
                    Missing = transition.MissingFrames,
                    KeyRoot = (double[])transition.KeyRootPositions.Clone(),
                    KeyRotations = (double[])transition.KeyLocalRotations.Clone(),
                });
                _slerp.Inbetween(transition);
            }
        }
    }
}
