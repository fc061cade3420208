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
