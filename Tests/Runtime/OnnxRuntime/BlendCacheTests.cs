using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Blends;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 28's Must-be-true for the neural Timeline track, on two real clips (the Demo sample's CMU walk and jumps,
    /// on one rig) and the shipped model: a blend's poses are the bake of the same two clips with the same model and
    /// history whatever order the playhead visits them in; its ends are the clips' own poses; what the bake reads
    /// (a clip, the timing, the model, the rig) invalidates it and nothing else does (network runs counted); and
    /// what the model cannot fill falls back, said once.
    /// </summary>
    [TestFixture]
    public sealed class BlendCacheTests
    {
        private const double Tolerance = 1e-5;

        private Inbetweener _model = null!;
        private CharacterRig _rig = null!;
        private MotionClip _demo = null!;
        private MotionClip _walk = null!;
        private MotionClip _jumps = null!;

        [OneTimeSetUp]
        public void Load()
        {
            DemoBlendClips clips = DemoBlendClips.Load();
            (_demo, _rig, _walk, _jumps) = (clips.Demo, clips.Rig, clips.Walk, clips.Jumps);
            _model = TwoRigBakeTests.ShippedModel();
        }

        [OneTimeTearDown]
        public void Unload() => _model?.Dispose();

        /// <summary>Walk 0–3 s, jumps from 2.5 s (clip-in 0.2 s): a 0.5 s blend, 14 missing frames at 30 fps.</summary>
        private static TrackLayout Blending(double jumpsStart = 2.5, double walkClipIn = 0) =>
            TrackLayout.Create(new[] { new TrackClipTiming(0, 3.0, walkClipIn, 3.0), new TrackClipTiming(jumpsStart, 3.0, 0.2, 401 / 120.0) });

        [Test]
        public void ABlendIsTheBakeOfItsClipsWhateverTheOrderOfTimes()
        {
            var network = new CountingNetwork(_model);
            var model = new BlendModel(_model.Contract, network, maxBoneDeviationDegrees: 30);
            var cache = new BlendCache();
            TrackLayout layout = Blending();
            TrackSpan span = layout.Spans[0];
            IClipPoses walk = new MotionClipPoses("walk", _rig, _walk), jumps = new MotionClipPoses("jumps", _rig, _jumps);
            BlendFrames frames = cache.Get(model, _rig, span, walk, jumps);
            Assert.That(frames.Mode, Is.EqualTo(BlendMode.Model));
            int n = model.MissingFrames(span.Duration);
            Assert.That(n, Is.EqualTo(14));
            Assert.That(frames.FrameCount, Is.EqualTo(n + 2));

            // The same bake, laid out by hand: the editor baker's Core path on the walk's 10 frames up to 2.5 s and the jumps at 0.7 s.
            int p = model.PastFrames;
            CharacterPoseTrack track = DemoBlendClips.LaidOut(_rig, p, n, 1 / 30.0, walk, k => span.FromTime - (p - 1 - k) / 30.0, jumps, 0.7);
            int bones = _rig.Skeleton.JointCount;
            var root = new double[3];
            var rotations = new double[4 * bones];
            MotionClip bake = CharacterBake.Run(_model.Contract, track, null, new[] { BakeMethod.Model(_model) }, null, 30).Methods[0].OnRig;

            // Model frames and points between them, visited at random, backwards and repeatedly, as a scrubbing playhead does.
            var times = new List<double>();
            for (int k = 0; k <= n + 1; k++) times.Add(span.Start + k * span.Duration / (n + 1));
            var random = new Random(28);
            for (int i = 0; i < 40; i++) times.Add(span.Start + random.NextDouble() * span.Duration);
            var order = new List<double>(times);
            Shuffle(order, random);
            var backwards = new List<double>(times);
            backwards.Sort();
            backwards.Reverse();
            order.AddRange(backwards);
            order.AddRange(new[] { times[3], times[3], times[3], times[0], times[3] });

            var expectedRoot = new double[3];
            var expectedRotations = new double[4 * bones];
            var frame = MotionClip.CreateRestPose(bake.Skeleton, 1, bake.FrameTime);
            double worst = 0;
            foreach (double t in order)
            {
                // Every evaluation asks the cache again, as a graph rebuilt at each scrub would.
                BlendFrames again = cache.Get(model, Rig(_demo, RootFrame.Identity), Blending().Spans[0], walk, jumps);
                Assert.That(again, Is.SameAs(frames), "an equal rig and layout rebuilt find the same blend");
                TrackMoment moment = layout.Locate(t);
                double fraction = moment.Fraction;
                if (t >= span.End)
                {
                    // The blend's end belongs to the clip it arrives in, at the time the blend's last frame was taken.
                    Assert.That((moment.Kind, moment.Clip, moment.LocalTime), Is.EqualTo((TrackMomentKind.Clip, 1, span.ToTime)));
                    fraction = 1;
                }
                else
                {
                    Assert.That(moment.Kind, Is.EqualTo(TrackMomentKind.Span), $"t = {t}");
                }

                Assert.That(frames.Sample(fraction, root, rotations), Is.True);
                double modelFrame = p - 1 + (t - span.Start) / span.Duration * (n + 1);
                MotionResampler.Sample(bake, modelFrame, frame.LocalPositions, frame.LocalRotations);
                CharacterPoseTrack.ReadUnityPose(_rig, frame, 0, expectedRoot, expectedRotations);
                worst = Math.Max(worst, Math.Max(Difference(root, expectedRoot), Difference(rotations, expectedRotations)));
            }

            TestContext.WriteLine($"{order.Count} evaluations, largest difference from the bake {worst:E2}; network runs {network.Runs}");
            Assert.That(worst, Is.LessThan(Tolerance));
            Assert.That(network.Runs, Is.EqualTo(1), "one network run for the blend, none per evaluation");
            Assert.That(cache.Computed, Is.EqualTo(1));

            // The comparison resolves what matters: the model's blend is not the SLERP of its ends.
            MotionClip slerp = CharacterBake.Run(_model.Contract, track, null, new[] { BakeMethod.Slerp() }, null, 30).Methods[0].OnRig;
            double apart = 0;
            for (int i = 0; i < slerp.LocalRotations.Length; i++) apart = Math.Max(apart, Math.Abs(slerp.LocalRotations[i] - bake.LocalRotations[i]));
            Assert.That(apart, Is.GreaterThan(1e-2));
        }

        [Test]
        public void TheFirstAndLastFramesAreTheClipsOwnPoses()
        {
            var model = new BlendModel(_model.Contract, _model, maxBoneDeviationDegrees: 30);
            var cache = new BlendCache();
            IClipPoses walk = new MotionClipPoses("walk", _rig, _walk), jumps = new MotionClipPoses("jumps", _rig, _jumps);
            // A blend and a gap (walk ends at 3 s, jumps start at 3.8 s: 23 missing frames).
            TrackLayout gapLayout = TrackLayout.Create(new[] { new TrackClipTiming(0, 3.0, 0, 3.0), new TrackClipTiming(3.8, 3.0, 0.2, 401 / 120.0) });
            foreach (TrackLayout layout in new[] { Blending(), gapLayout })
            {
                TrackSpan span = layout.Spans[0];
                BlendFrames frames = cache.Get(model, _rig, span, walk, jumps);
                Assert.That(frames.Mode, Is.EqualTo(BlendMode.Model), span.Kind.ToString());
                int bones = _rig.Skeleton.JointCount;
                double[] root = new double[3], rotations = new double[4 * bones], clipRoot = new double[3], clipRotations = new double[4 * bones];
                frames.Sample(0, root, rotations);
                walk.Sample(span.FromTime, clipRoot, clipRotations);
                Assert.That(Math.Max(Difference(root, clipRoot), Difference(rotations, clipRotations)), Is.LessThan(Tolerance), $"{span.Kind}: the first frame is the walk's pose at {span.FromTime} s");
                frames.Sample(1, root, rotations);
                TrackMoment arrival = layout.Locate(span.End);
                Assert.That(arrival.Clip, Is.EqualTo(1));
                jumps.Sample(arrival.LocalTime, clipRoot, clipRotations);
                Assert.That(Math.Max(Difference(root, clipRoot), Difference(rotations, clipRotations)), Is.LessThan(Tolerance), $"{span.Kind}: the last frame is the pose the jumps clip plays on at {span.End} s");
            }
        }

        [Test]
        public void WhatTheBakeReadsInvalidatesABlendAndNothingElseDoes()
        {
            var network = new CountingNetwork(_model);
            var model = new BlendModel(_model.Contract, network, maxBoneDeviationDegrees: 30);
            var cache = new BlendCache();
            IClipPoses walk = new MotionClipPoses("walk", _rig, _walk), jumps = new MotionClipPoses("jumps", _rig, _jumps);
            BlendFrames first = cache.Get(model, _rig, Blending().Spans[0], walk, jumps);
            Assert.That(network.Runs, Is.EqualTo(1));

            // Unchanged: a rebuilt graph (new layout, new rig object, new clip sources of the same clips), both clips moved together.
            var rebuiltRig = Rig(_demo, RootFrame.Identity);
            Assert.That(cache.Get(model, rebuiltRig, Blending().Spans[0], new MotionClipPoses("walk", rebuiltRig, _walk), new MotionClipPoses("jumps", rebuiltRig, _jumps)), Is.SameAs(first));
            Assert.That(network.Runs, Is.EqualTo(1), "an unchanged graph rebuild runs no network");
            // The jumps clip changed after the frame the blend arrives at: no key of the blend changed, nothing to recompute.
            MotionClip laterChanged = Turned(_jumps, 200, _jumps.FrameCount);
            Assert.That(cache.Get(model, _rig, Blending().Spans[0], walk, new MotionClipPoses("jumps", _rig, laterChanged)), Is.SameAs(first));
            Assert.That(network.Runs, Is.EqualTo(1));

            // A clip changed where its keys are read: the walk's frames before the blend.
            MotionClip walkChanged = Turned(_walk, 250, 300);
            Assert.That(cache.Get(model, _rig, Blending().Spans[0], new MotionClipPoses("walk", _rig, walkChanged), jumps), Is.Not.SameAs(first));
            Assert.That(network.Runs, Is.EqualTo(2), "a changed clip");
            // The target clip changed at the blend's end.
            Assert.That(cache.Get(model, _rig, Blending().Spans[0], walk, new MotionClipPoses("jumps", _rig, Turned(_jumps, 0, 200))), Is.Not.SameAs(first));
            Assert.That(network.Runs, Is.EqualTo(3), "a changed target clip");
            // Timing: a longer blend; and the walk's clip-in (the same blend length, other history).
            cache.Get(model, _rig, Blending(jumpsStart: 2.4).Spans[0], walk, jumps);
            Assert.That(network.Runs, Is.EqualTo(4), "a longer blend");
            cache.Get(model, _rig, Blending(walkClipIn: 0.3).Spans[0], walk, jumps);
            Assert.That(network.Runs, Is.EqualTo(5), "another clip-in");
            // The model: another network object (a model re-imported or swapped).
            using (Inbetweener other = TwoRigBakeTests.ShippedModel())
            {
                var otherNetwork = new CountingNetwork(other);
                cache.Get(new BlendModel(other.Contract, otherNetwork, maxBoneDeviationDegrees: 30), _rig, Blending().Spans[0], walk, jumps);
                Assert.That(otherNetwork.Runs, Is.EqualTo(1), "another model");
            }

            // The rig: the same bones under a turned armature.
            var turned = new RootFrame(Vector3D.Zero, Quaternions.FromAxisAngle(new Vector3D(0, 1, 0), 0.5), 1);
            CharacterRig otherRig = Rig(_demo, turned);
            cache.Get(model, otherRig, Blending().Spans[0], new MotionClipPoses("walk", otherRig, _walk), new MotionClipPoses("jumps", otherRig, _jumps));
            Assert.That(network.Runs, Is.EqualTo(6), "another rig");

            // And the first blend is still served: nothing above evicted it.
            Assert.That(cache.Get(model, _rig, Blending().Spans[0], walk, jumps), Is.SameAs(first));
            Assert.That(network.Runs, Is.EqualTo(6));
        }

        [Test]
        public void WhatTheModelCannotFillFallsBackSaidOnce()
        {
            var network = new CountingNetwork(_model);
            var model = new BlendModel(_model.Contract, network, maxBoneDeviationDegrees: 30);
            var cache = new BlendCache();
            IClipPoses walk = new MotionClipPoses("walk", _rig, _walk), jumps = new MotionClipPoses("jumps", _rig, _jumps);
            var said = new List<string>();

            // A 2 s gap: 59 missing frames, past the 39 the model was trained on: SLERP, through the same bake path.
            TrackLayout longGap = TrackLayout.Create(new[] { new TrackClipTiming(0, 3.0, 0, 3.0), new TrackClipTiming(5.0, 3.0, 0.2, 401 / 120.0) });
            BlendFrames gap = null!;
            for (int i = 0; i < 5; i++) gap = cache.Get(model, _rig, longGap.Spans[0], walk, jumps, said.Add);
            Assert.That(gap.Mode, Is.EqualTo(BlendMode.Slerp));
            Assert.That(said.Count, Is.EqualTo(1), "said once");
            Assert.That(said[0], Does.Contain("59 missing frames").And.Contain("SLERP"));
            Assert.That(network.Runs, Is.EqualTo(0));
            var track = new CharacterPoseTrack(_rig, 61, 1 / 30.0);
            int bones = _rig.Skeleton.JointCount;
            double[] root = new double[3], rotations = new double[4 * bones], expectedRoot = new double[3], expectedRotations = new double[4 * bones];
            walk.Sample(3.0, root, rotations);
            track.SetUnityPose(0, root, rotations);
            jumps.Sample(0.2, root, rotations);
            track.SetUnityPose(60, root, rotations);
            MotionClip slerp = CharacterBake.Run(_model.Contract, track, null, new[] { BakeMethod.Slerp() }, null, 30).Methods[0].OnRig;
            for (int k = 0; k <= 60; k++)
            {
                gap.Sample(k / 60.0, root, rotations);
                CharacterPoseTrack.ReadUnityPose(_rig, slerp, k, expectedRoot, expectedRotations);
                Assert.That(Math.Max(Difference(root, expectedRoot), Difference(rotations, expectedRotations)), Is.LessThan(Tolerance), $"SLERP frame {k}");
            }

            // A 0.1 s blend: 2 missing frames, under the 5 trained on: Timeline's crossfade, no frames.
            said.Clear();
            TrackLayout shortBlend = Blending(jumpsStart: 2.9);
            BlendFrames blend = null!;
            for (int i = 0; i < 5; i++) blend = cache.Get(model, _rig, shortBlend.Spans[0], walk, jumps, said.Add);
            Assert.That(blend.Mode, Is.EqualTo(BlendMode.Crossfade));
            Assert.That(blend.Sample(0.5, root, rotations), Is.False, "a crossfade has no frames: the mixer plays Timeline's weights");
            Assert.That(said.Count, Is.EqualTo(1), "said once");
            Assert.That(said[0], Does.Contain("2 missing frames").And.Contain("crossfade"));
            Assert.That(network.Runs, Is.EqualTo(0));
        }

        [Test]
        public void AGapUnderOneMissingFrameIsTheSlerpOfItsPosesAndAThirdClipInABlendCrossfades()
        {
            var network = new CountingNetwork(_model);
            var model = new BlendModel(_model.Contract, network, maxBoneDeviationDegrees: 30);
            var cache = new BlendCache();
            IClipPoses walk = new MotionClipPoses("walk", _rig, _walk), jumps = new MotionClipPoses("jumps", _rig, _jumps);
            var said = new List<string>();
            // 1/30 s between the clips: one model frame, no missing frame to fill.
            TrackLayout tiny = TrackLayout.Create(new[] { new TrackClipTiming(0, 3.0, 0, 3.0), new TrackClipTiming(3.0 + 1 / 30.0, 3.0, 0.2, 401 / 120.0) });
            BlendFrames gap = cache.Get(model, _rig, tiny.Spans[0], walk, jumps, said.Add);
            Assert.That((gap.Mode, gap.FrameCount), Is.EqualTo((BlendMode.Slerp, 2)));
            int bones = _rig.Skeleton.JointCount;
            double[] root = new double[3], rotations = new double[4 * bones], clipRoot = new double[3], clipRotations = new double[4 * bones];
            gap.Sample(0, root, rotations);
            walk.Sample(3.0, clipRoot, clipRotations);
            Assert.That(Math.Max(Difference(root, clipRoot), Difference(rotations, clipRotations)), Is.LessThan(Tolerance));
            gap.Sample(1, root, rotations);
            jumps.Sample(0.2, clipRoot, clipRotations);
            Assert.That(Math.Max(Difference(root, clipRoot), Difference(rotations, clipRotations)), Is.LessThan(Tolerance));
            Assert.That(said.Count, Is.EqualTo(1));

            // A third clip starting inside the walk → jumps blend: Timeline's crossfade, said once however often the graph is rebuilt.
            said.Clear();
            TrackLayout three = TrackLayout.Create(new[] { new TrackClipTiming(0, 3.0, 0, 3.0), new TrackClipTiming(2.5, 3.0, 0.2, 401 / 120.0), new TrackClipTiming(2.8, 1.0, 0, 3.0) });
            for (int i = 0; i < 3; i++) Assert.That(cache.Get(model, _rig, three.Spans[0], walk, jumps, said.Add).Mode, Is.EqualTo(BlendMode.Crossfade));
            Assert.That(said.Count, Is.EqualTo(1));
            Assert.That(said[0], Does.Contain("starts inside the blend"));
            Assert.That(network.Runs, Is.EqualTo(0));
        }

        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void ReadingABlendAtThePlayheadAllocatesNothing()
        {
            var model = new BlendModel(_model.Contract, _model, maxBoneDeviationDegrees: 30);
            TrackLayout layout = Blending();
            BlendFrames frames = new BlendCache().Get(model, _rig, layout.Spans[0], new MotionClipPoses("walk", _rig, _walk), new MotionClipPoses("jumps", _rig, _jumps));
            int bones = _rig.Skeleton.JointCount;
            double[] root = new double[3], rotations = new double[4 * bones];
            void Frame(int i)
            {
                TrackMoment moment = layout.Locate(2.5 + (i % 50) / 100.0);
                frames.Sample(moment.Fraction, root, rotations);
            }

            // Warm-up past the runtime's tiered compilation (its first calls and loops are recompiled, which can count as this thread's bytes).
            for (int i = 0; i < 2000; i++) Frame(i);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 1000; i++) Frame(i);
            long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
            TestContext.WriteLine($"1000 playhead reads: {bytes} bytes allocated");
            Assert.That(bytes, Is.EqualTo(0), "the mixer's per-frame path (Locate, Sample) allocates nothing");
        }

        [Test]
        public void RefusesWhatIsNoCacheOrModel()
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => _ = new BlendCache(0));
            Assert.That(e!.ParamName, Is.EqualTo("capacity"));
            var m = Assert.Throws<ArgumentOutOfRangeException>(() => _ = new BlendModel(_model.Contract, _model, maxBoneDeviationDegrees: double.NaN));
            Assert.That(m!.ParamName, Is.EqualTo("maxBoneDeviationDegrees"));
            var p = Assert.Throws<ArgumentException>(() => _ = new MotionClipPoses("short", _rig, _walk.Excerpt(0, 2) is var c ? new MotionClip(new Skeleton(new[] { "Hips" }, new[] { -1 }, new double[3]), 2, c.FrameTime, new double[6], new[] { 1.0, 0, 0, 0, 1, 0, 0, 0 }) : c));
            Assert.That(p!.ParamName, Is.EqualTo("motion"));
        }

        /// <summary>The rig the Unity layer would collect from the demo's T-pose frame: Unity's space under <paramref name="armature"/>.</summary>
        internal static CharacterRig Rig(MotionClip clip, RootFrame armature)
        {
            Skeleton s = clip.Skeleton;
            int n = s.JointCount;
            var positions = new double[3 * n];
            var rotations = new double[4 * n];
            for (int b = 0; b < n; b++)
            {
                Vector3D unity = Handedness.PositionToUnity(Vector3D.Read(s.OffsetSpan, 3 * b));
                (b == 0 ? armature.PointFromParent(unity) : unity).Write(positions, 3 * b);
                QuaternionD q = Handedness.RotationToUnity(QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(0, b)));
                (b == 0 ? armature.RotationFromParent(q) : q).Write(rotations, 4 * b);
            }

            return new CharacterRig("cmu", s.Names, s.Parents, positions, rotations, armature);
        }

        /// <summary>A copy of <paramref name="clip"/> whose root turns 20° more on frames first..end−1.</summary>
        private static MotionClip Turned(MotionClip clip, int first, int end)
        {
            var rotations = (double[])clip.LocalRotations.Clone();
            QuaternionD turn = Quaternions.FromAxisAngle(new Vector3D(0, 1, 0), 20 * Math.PI / 180);
            for (int f = first; f < end; f++) Quaternions.Multiply(turn, QuaternionD.Read(rotations, clip.RotationIndex(f, 0))).Write(rotations, clip.RotationIndex(f, 0));
            return new MotionClip(clip.Skeleton, clip.FrameCount, clip.FrameTime, (double[])clip.LocalPositions.Clone(), rotations);
        }

        private static double Difference(double[] a, double[] b)
        {
            double worst = 0;
            for (int i = 0; i < a.Length; i++) worst = Math.Max(worst, Math.Abs(a[i] - b[i]));
            return worst;
        }

        private static void Shuffle(List<double> list, Random random)
        {
            for (int i = list.Count - 1; i > 0; i--)
            {
                int j = random.Next(i + 1);
                (list[i], list[j]) = (list[j], list[i]);
            }
        }

        /// <summary>The real network, its runs counted.</summary>
        private sealed class CountingNetwork : IInbetweener
        {
            private readonly IInbetweener _inner;

            public CountingNetwork(IInbetweener inner) => _inner = inner;

            public int Runs { get; private set; }

            public string Id => _inner.Id;

            public string DisplayName => _inner.DisplayName;

            public void Inbetween(Transition transition)
            {
                Runs++;
                _inner.Inbetween(transition);
            }
        }
    }
}
