using System;
using DeltaInterpolator.Core.Blends;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Blends
{
    /// <summary>What a neural track plays where (issue 28, item 1): clips alone, blends where they overlap, gaps between them.</summary>
    [TestFixture]
    public sealed class TrackLayoutTests
    {
        [Test]
        public void OverlapsAreBlendsAndTimeBetweenClipsIsAGap()
        {
            // Given out of track order: the indices in the result are the caller's.
            TrackLayout layout = TrackLayout.Create(new[]
            {
                new TrackClipTiming(5.0, 2.0, 0.25, 3.0), // 2: after a gap of 0.8 s
                new TrackClipTiming(0.0, 3.0, 0.0, 3.0), // 0
                new TrackClipTiming(2.5, 1.7, 0.1, 4.0), // 1: overlaps 0 by 0.5 s
            });
            Assert.That(layout.Spans.Count, Is.EqualTo(2));
            TrackSpan blend = layout.Spans[0], gap = layout.Spans[1];
            Assert.That((blend.Kind, blend.From, blend.To), Is.EqualTo((TrackSpanKind.Blend, 1, 2)));
            Assert.That((blend.Start, blend.End), Is.EqualTo((2.5, 3.0)));
            Assert.That(blend.FromTime, Is.EqualTo(2.5), "clip 1's (A's) time where the blend starts");
            Assert.That(blend.ToTime, Is.EqualTo(0.1 + 0.5).Within(1e-12), "clip 2's (B's) time where the blend ends: clip-in + 0.5 s");
            Assert.That(blend.CrossfadeReason, Is.Null);
            Assert.That((gap.Kind, gap.From, gap.To), Is.EqualTo((TrackSpanKind.Gap, 2, 0)));
            Assert.That(gap.Start, Is.EqualTo(4.2).Within(1e-12));
            Assert.That(gap.End, Is.EqualTo(5.0));
            Assert.That(gap.FromTime, Is.EqualTo(1.8).Within(1e-12), "A's last frame: clip-in 0.1 + 1.7 s");
            Assert.That(gap.ToTime, Is.EqualTo(0.25), "B's first frame: its clip-in");

            Assert.That(layout.Locate(-0.1).Kind, Is.EqualTo(TrackMomentKind.None));
            TrackMoment alone = layout.Locate(1.0);
            Assert.That((alone.Kind, alone.Clip, alone.LocalTime), Is.EqualTo((TrackMomentKind.Clip, 1, 1.0)));
            TrackMoment inBlend = layout.Locate(2.75);
            Assert.That((inBlend.Kind, inBlend.Span), Is.EqualTo((TrackMomentKind.Span, 0)));
            Assert.That(inBlend.Fraction, Is.EqualTo(0.5).Within(1e-12));
            TrackMoment after = layout.Locate(3.0);
            Assert.That((after.Kind, after.Clip), Is.EqualTo((TrackMomentKind.Clip, 2)), "a span's end belongs to the clip after it");
            Assert.That(after.LocalTime, Is.EqualTo(blend.ToTime).Within(1e-12), "where the blend arrives");
            Assert.That(layout.Locate(4.6).Span, Is.EqualTo(1));
            Assert.That(layout.Locate(7.5).Kind, Is.EqualTo(TrackMomentKind.None));
        }

        [Test]
        public void ClipsThatMeetCutAndBlendsTimelineCannotMakeAreCrossfades()
        {
            TrackLayout cut = TrackLayout.Create(new[] { new TrackClipTiming(0, 1, 0, 1), new TrackClipTiming(1, 1, 0, 1) });
            Assert.That(cut.Spans, Is.Empty);

            TrackLayout inside = TrackLayout.Create(new[] { new TrackClipTiming(0, 3, 0, 3), new TrackClipTiming(1, 1, 0, 1) });
            Assert.That(inside.Spans[0].CrossfadeReason, Does.Contain("inside"));

            TrackLayout three = TrackLayout.Create(new[] { new TrackClipTiming(0, 2, 0, 2), new TrackClipTiming(1, 2, 0, 2), new TrackClipTiming(1.5, 2, 0, 2) });
            Assert.That(three.Spans[0].CrossfadeReason, Does.Contain("clip 2 starts inside"));
            Assert.That(three.Spans[1].CrossfadeReason, Does.Contain("clip 0 still plays"));
        }

        [Test]
        public void AnimationTimeIsHeldAtTheAnimationsEnds()
        {
            var clip = new TrackClipTiming(1.0, 5.0, 0.5, 2.0);
            Assert.That(clip.LocalTime(1.0), Is.EqualTo(0.5));
            Assert.That(clip.LocalTime(2.0), Is.EqualTo(1.5));
            Assert.That(clip.LocalTime(5.0), Is.EqualTo(2.0), "past the animation's length: its last frame");
            Assert.That(clip.LocalTime(0.0), Is.EqualTo(0.0));
        }

        [Test]
        public void ALoopingClipWrapsAndAFasterClipAdvancesFaster()
        {
            var loop = new TrackClipTiming(1.0, 5.0, 0.5, 2.0, loops: true);
            Assert.That(loop.LocalTime(2.0), Is.EqualTo(1.5));
            Assert.That(loop.LocalTime(3.0), Is.EqualTo(0.5).Within(1e-12), "2.5 s into a 2 s loop: 0.5 s into its second cycle");
            Assert.That(loop.LocalTime(5.75), Is.EqualTo(1.25).Within(1e-12));
            Assert.That(loop.LocalTime(0.0), Is.EqualTo(0.0), "before the animation's first frame");
            var fast = new TrackClipTiming(1.0, 1.0, 0.5, 2.0, speed: 2);
            Assert.That(fast.LocalTime(1.5), Is.EqualTo(1.5));
            Assert.That(fast.LocalTime(2.0), Is.EqualTo(2.0), "held at the last frame: it does not loop");
            Assert.That(fast.Unwrapped(2.0), Is.EqualTo(2.5));

            TrackLayout layout = TrackLayout.Create(new[] { loop, new TrackClipTiming(5.5, 1.0, 0.0, 1.0, speed: 0.5) });
            TrackSpan blend = layout.Spans[0];
            Assert.That(blend.FromTime, Is.EqualTo(1.0).Within(1e-12), "the loop's time where the blend starts (5.0 s in: 2.5 cycles)");
            Assert.That(blend.ToTime, Is.EqualTo(0.25).Within(1e-12), "half a second at half speed");
            Assert.That(layout.Locate(6.0).LocalTime, Is.EqualTo(0.25).Within(1e-12));
        }

        [Test]
        public void BeforeTheFirstClipAndAfterTheLastTheirExtrapolationPlaysAsOnAnAnimationTrack()
        {
            // A clip at 2–4 s on the track, clip-in 0.5 s, at speed 1.5 of a 5 s animation; times as Timeline's
            // TimelineClip.ToLocalTime gives them (extrapolated over the clip's 2 s, then × speed + clip-in).
            TrackClipTiming Clip(TrackExtrapolation pre, TrackExtrapolation post, bool loops = false) =>
                new TrackClipTiming(2.0, 2.0, 0.5, 5.0, 1.5, loops, pre, post);
            var cases = new (TrackExtrapolation Mode, double Time, double Expected)[]
            {
                (TrackExtrapolation.Hold, 0.5, 0.5), // held at the clip's first frame: its clip-in
                (TrackExtrapolation.Hold, 5.0, 0.5 + 2.0 * 1.5), // held at its last: 3.5 s
                (TrackExtrapolation.Loop, 0.5, 0.5 + (2.0 - 1.5) * 1.5), // 1.5 s before the start = 0.5 s into the previous cycle
                (TrackExtrapolation.Loop, 5.25, 0.5 + 1.25 * 1.5), // 3.25 s after the start = 1.25 s into the second cycle
                (TrackExtrapolation.PingPong, 5.25, 0.5 + 0.75 * 1.5), // 1.25 s into the way back: 0.75 s from the start
                (TrackExtrapolation.PingPong, 1.5, 0.5 + 0.5 * 1.5), // mirrored before the start
                (TrackExtrapolation.Continue, 4.5, 0.5 + 2.5 * 1.5), // time runs on: 4.25 s
                (TrackExtrapolation.Continue, 1.0, 0.0), // before the animation's first frame: held there (it does not loop)
            };
            foreach (var (mode, time, expected) in cases)
            {
                bool before = time < 2.0;
                TrackLayout layout = TrackLayout.Create(new[] { before ? Clip(mode, TrackExtrapolation.None) : Clip(TrackExtrapolation.None, mode) });
                TrackMoment moment = layout.Locate(time);
                Assert.That((moment.Kind, moment.Clip, moment.Extrapolation), Is.EqualTo((TrackMomentKind.Clip, 0, mode)), $"{mode} at {time} s");
                Assert.That(moment.LocalTime, Is.EqualTo(expected).Within(1e-12), $"{mode} at {time} s");
            }

            // A looping animation wraps the extrapolated time, before its first frame too (4.25 s of a 3 s loop: 1.25 s).
            var loop = new TrackClipTiming(2.0, 2.0, 0.5, 3.0, 1.5, true, TrackExtrapolation.Continue, TrackExtrapolation.Continue);
            Assert.That(TrackLayout.Create(new[] { loop }).Locate(4.5).LocalTime, Is.EqualTo(1.25).Within(1e-12));
            Assert.That(TrackLayout.Create(new[] { loop }).Locate(1.0).LocalTime, Is.EqualTo(3.0 - 1.0).Within(1e-12), "−1 s wraps to 2 s");

            // None (a clip on a neural track by default) plays nothing there; nor does anything before track time 0.
            TrackLayout none = TrackLayout.Create(new[] { Clip(TrackExtrapolation.None, TrackExtrapolation.None) });
            Assert.That(none.Locate(1.0).Kind, Is.EqualTo(TrackMomentKind.None));
            Assert.That(none.Locate(4.5).Kind, Is.EqualTo(TrackMomentKind.None));
            Assert.That(TrackLayout.Create(new[] { Clip(TrackExtrapolation.Hold, TrackExtrapolation.Hold) }).Locate(-0.5).Kind, Is.EqualTo(TrackMomentKind.None));

            // With two clips, only the first one's pre- and the last one's post-extrapolation reach outside them.
            TrackLayout two = TrackLayout.Create(new[]
            {
                new TrackClipTiming(3.0, 1.0, 0, 1, 1, false, TrackExtrapolation.Loop, TrackExtrapolation.Hold),
                new TrackClipTiming(1.0, 1.0, 0, 1, 1, false, TrackExtrapolation.Hold, TrackExtrapolation.Continue),
            });
            Assert.That((two.Locate(0.5).Clip, two.Locate(0.5).Extrapolation), Is.EqualTo((1, TrackExtrapolation.Hold)));
            Assert.That((two.Locate(4.5).Clip, two.Locate(4.5).Extrapolation, two.Locate(4.5).LocalTime), Is.EqualTo((0, TrackExtrapolation.Hold, 1.0)));
            Assert.That(two.Locate(2.5).Kind, Is.EqualTo(TrackMomentKind.Span), "between them: the gap, the model's");
        }

        [Test]
        public void AGapIsTheModelsAndAnExplicitLoopPingPongOrContinueBesideItIsSaidOverridden()
        {
            TrackSpan Gap(TrackExtrapolation aPost, TrackExtrapolation bPre) => TrackLayout.Create(new[]
            {
                new TrackClipTiming(0.0, 2.0, 0, 2, 1, false, TrackExtrapolation.Hold, aPost),
                new TrackClipTiming(2.6, 2.0, 0, 2, 1, false, bPre, TrackExtrapolation.Hold),
            }).Spans[0];

            // Hold (an Animation Track's default) and None (a neural track's): the in-between, nothing to say.
            foreach (TrackExtrapolation quiet in new[] { TrackExtrapolation.Hold, TrackExtrapolation.None })
            {
                TrackSpan gap = Gap(quiet, TrackExtrapolation.None);
                Assert.That((gap.Kind, gap.Extrapolation, gap.ExtrapolationOverridden), Is.EqualTo((TrackSpanKind.Gap, quiet, (string?)null)));
            }

            // The first clip's post-extrapolation fills a gap; the second's pre only where the first has none (as Timeline).
            TrackSpan loop = Gap(TrackExtrapolation.Loop, TrackExtrapolation.PingPong);
            Assert.That(loop.Extrapolation, Is.EqualTo(TrackExtrapolation.Loop));
            Assert.That(loop.ExtrapolationOverridden, Does.StartWith("clip 0's post-extrapolation is Loop").And.Contain("; expected Hold or None"));
            TrackSpan hold = Gap(TrackExtrapolation.Hold, TrackExtrapolation.Continue);
            Assert.That((hold.Extrapolation, hold.ExtrapolationOverridden), Is.EqualTo((TrackExtrapolation.Hold, (string?)null)), "B's pre is not played after A's Hold");
            TrackSpan pingPong = Gap(TrackExtrapolation.None, TrackExtrapolation.PingPong);
            Assert.That(pingPong.ExtrapolationOverridden, Does.StartWith("clip 1's pre-extrapolation is PingPong"));
            Assert.That(Gap(TrackExtrapolation.Continue, TrackExtrapolation.None).ExtrapolationOverridden, Does.Contain("Continue"));

            // A blend has no extrapolation of its own.
            TrackSpan blend = TrackLayout.Create(new[]
            {
                new TrackClipTiming(0.0, 2.0, 0, 2, 1, false, TrackExtrapolation.Loop, TrackExtrapolation.Loop),
                new TrackClipTiming(1.5, 2.0, 0, 2, 1, false, TrackExtrapolation.Loop, TrackExtrapolation.Loop),
            }).Spans[0];
            Assert.That((blend.Extrapolation, blend.ExtrapolationOverridden), Is.EqualTo((TrackExtrapolation.None, (string?)null)));
        }

        [TestCase(-1, 0, "preExtrapolation")]
        [TestCase(0, 5, "postExtrapolation")]
        [TestCase(int.MaxValue, 0, "preExtrapolation")]
        public void RefusesAnExtrapolationTimelineDoesNotHave(int pre, int post, string parameter)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => _ = new TrackClipTiming(0, 1, 0, 1, 1, false, (TrackExtrapolation)pre, (TrackExtrapolation)post));
            Assert.That(e!.ParamName, Is.EqualTo(parameter));
            Assert.That(e.Message, Does.Contain("expected None, Hold, Loop, PingPong or Continue"));
        }

        [TestCase(-1.0, 1.0, 0.0, 1.0, "start")]
        [TestCase(double.NaN, 1.0, 0.0, 1.0, "start")]
        [TestCase(0.0, 0.0, 0.0, 1.0, "duration")]
        [TestCase(0.0, double.PositiveInfinity, 0.0, 1.0, "duration")]
        [TestCase(0.0, 1.0, -0.5, 1.0, "clipIn")]
        [TestCase(0.0, 1.0, 0.0, double.NaN, "animationLength")]
        [TestCase(0.0, 1.0, 0.0, -2.0, "animationLength")]
        public void RefusesATimingThatIsNoClipPlacement(double start, double duration, double clipIn, double length, string parameter)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => _ = new TrackClipTiming(start, duration, clipIn, length));
            Assert.That(e!.ParamName, Is.EqualTo(parameter));
            Assert.That(e.Message, Does.Contain("expected"));
        }

        [Test]
        public void RefusesTwoClipsAtOneStart()
        {
            var e = Assert.Throws<ArgumentException>(() => TrackLayout.Create(new[] { new TrackClipTiming(1, 1, 0, 1), new TrackClipTiming(1, 2, 0, 2) }));
            Assert.That(e!.ParamName, Is.EqualTo("clips"));
            Assert.That(e.Message, Does.Contain("; expected"));
            Assert.Throws<ArgumentNullException>(() => TrackLayout.Create(null!));
        }
    }
}
