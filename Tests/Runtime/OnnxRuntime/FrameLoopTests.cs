using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using System.Linq;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Playback;
using DeltaInterpolator.Tests.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The component's per-frame logic (<see cref="TransitionPlayer"/>) in a simulated game loop on the real
    /// ONNX Runtime with the tiny fixture model: a character plays its own animation, a transition is
    /// requested mid-clip, and every rendered frame is checked against the Core in-betweener run on the
    /// same request. Frame times are fixed (30 fps, the model's rate) or variable (144 fps ± 25 % jitter).
    /// </summary>
    [TestFixture]
    public sealed class FrameLoopTests
    {
        private const double BlendIn = 0.1;
        private const double BlendOut = 0.2;

        public enum Decoding
        {
            WorkerThread,
            MainThread,
        }

        [TestCase(30.0, 0.0, Decoding.WorkerThread)]
        [TestCase(144.0, 0.25, Decoding.WorkerThread)]
        [TestCase(30.0, 0.0, Decoding.MainThread)]
        [TestCase(144.0, 0.25, Decoding.MainThread)]
        public void TransitionMidClipStartsFromShownPoseReachesTargetOnItsFrameAndEqualsInbetweener(double fps, double jitter, Decoding decoding)
        {
            using var loop = new FrameLoop(fps, jitter, decoding, seed: 3);
            loop.PlayUntil(1.3);
            // Before any request the character shows its own animation.
            loop.AssertShowsClip();
            double shownAt = loop.Time;
            double[] shownRoot = (double[])loop.Shown.Root.Clone();
            double[] shownRotations = (double[])loop.Shown.Rotations.Clone();
            var (targetRoot, targetRotations) = loop.ClipPose(4.0);
            const double duration = 0.5;
            int id = loop.Player.RequestTransition(targetRoot, targetRotations, duration);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);
            Transition keys = loop.Player.CurrentTransition!;

            // Starts from the character's current pose: the last past key is the pose shown, and the past
            // keys are the clip resampled at the model's 30 fps.
            loop.AssertKeyIs(keys, keys.PastFrames - 1, shownRoot, shownRotations, 1e-12);
            double keyTolerance = fps == 30.0 ? 1e-9 : 2e-3;
            for (int i = 0; i < keys.PastFrames; i++)
            {
                var (root, rotations) = loop.ClipPose(shownAt - (keys.PastFrames - 1 - i) / 30.0);
                loop.AssertKeyIs(keys, i, root, rotations, keyTolerance);
            }

            double[][] expectedRoots;
            double[][] expectedRotations;
            loop.ExpectedFrames(keys, out expectedRoots, out expectedRotations);
            double targetTime = shownAt + duration;
            int checkedFrames = 0;
            while (loop.Time + loop.NextStep < targetTime - 1e-9)
            {
                loop.Step();
                Assert.That(loop.Completions, Is.Empty, $"completed early at {loop.Time}");
                double s = loop.Time - shownAt;
                if (s < BlendIn) continue;
                Assert.That(loop.Player.Weight, Is.EqualTo(1.0));
                loop.AssertShowsModelTime(s / duration * loop.Player.GapFrames, expectedRoots, expectedRotations, 1e-5);
                checkedFrames++;
            }

            Assert.That(checkedFrames, Is.GreaterThanOrEqualTo(fps == 30.0 ? 11 : 50), "frames checked between the blend windows");
            // The first rendered frame at or after the target time shows the target, and completes the request.
            loop.Step();
            Assert.That(loop.Time, Is.GreaterThanOrEqualTo(targetTime - 1e-9));
            loop.AssertShows(targetRoot, targetRotations, 1e-12);
            Assert.That(loop.Completions.Count, Is.EqualTo(1));
            Assert.That(loop.Completions[0].RequestId, Is.EqualTo(id));
            Assert.That(loop.Completions[0].ReachedTarget, Is.True);
            Assert.That(loop.Completions[0].Time, Is.EqualTo(loop.Time));

            // Blend out, then back to the character's own animation; the event never fires again.
            loop.PlayUntil(loop.Time + BlendOut + 0.1);
            Assert.That(loop.Player.IsPlaying, Is.False);
            loop.AssertShowsClip();
            Assert.That(loop.Completions.Count, Is.EqualTo(1));
        }

        [TestCase(30.0, 0.0, Decoding.WorkerThread)]
        [TestCase(144.0, 0.25, Decoding.WorkerThread)]
        [TestCase(144.0, 0.25, Decoding.MainThread)]
        public void NewRequestDuringATransitionStartsFromThePoseBeingShown(double fps, double jitter, Decoding decoding)
        {
            using var loop = new FrameLoop(fps, jitter, decoding, seed: 5);
            loop.PlayUntil(1.0);
            var (rootA, rotationsA) = loop.ClipPose(3.0);
            int first = loop.Player.RequestTransition(rootA, rotationsA, 0.6);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);
            loop.PlayUntil(loop.Time + 0.3);
            Assert.That(loop.Player.Weight, Is.EqualTo(1.0));
            Assert.That(loop.Completions, Is.Empty);

            // Mid-transition: the shown pose is the transition's, not the clip's.
            double shownAt = loop.Time;
            double[] shownRoot = (double[])loop.Shown.Root.Clone();
            double[] shownRotations = (double[])loop.Shown.Rotations.Clone();
            var (clipRoot, clipRotations) = loop.ClipPose(shownAt);
            Assert.That(MaxDifference(shownRotations, clipRotations), Is.GreaterThan(0.05), "the transition must show something else than the clip");
            var (rootB, rotationsB) = loop.ClipPose(6.0);
            int second = loop.Player.RequestTransition(rootB, rotationsB, 0.4);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);

            // The interrupted request completed once, not reached; the new one starts from the pose shown.
            Assert.That(loop.Completions.Count, Is.EqualTo(1));
            Assert.That(loop.Completions[0].RequestId, Is.EqualTo(first));
            Assert.That(loop.Completions[0].ReachedTarget, Is.False);
            Transition keys = loop.Player.CurrentTransition!;
            loop.AssertKeyIs(keys, keys.PastFrames - 1, shownRoot, shownRotations, 1e-12);

            // Continuous: the next frame moves from the pose shown by no more than the motion allows.
            double[] before = (double[])loop.Shown.Rotations.Clone();
            loop.Step();
            Assert.That(loop.Player.Weight, Is.EqualTo(1.0));
            Assert.That(MaxDifference(loop.Shown.Rotations, before), Is.LessThan(0.1));

            double[][] expectedRoots;
            double[][] expectedRotations;
            loop.ExpectedFrames(keys, out expectedRoots, out expectedRotations);
            double targetTime = shownAt + 0.4;
            while (loop.Time + loop.NextStep < targetTime - 1e-9)
            {
                loop.Step();
                loop.AssertShowsModelTime((loop.Time - shownAt) / 0.4 * loop.Player.GapFrames, expectedRoots, expectedRotations, 1e-5);
            }

            loop.Step();
            loop.AssertShows(rootB, rotationsB, 1e-12);
            Assert.That(loop.Completions.Count, Is.EqualTo(2));
            Assert.That(loop.Completions[1].RequestId, Is.EqualTo(second));
            Assert.That(loop.Completions[1].ReachedTarget, Is.True);
            loop.PlayUntil(loop.Time + 1);
            Assert.That(loop.Completions.Count, Is.EqualTo(2));
        }

        [Test]
        public void WithoutWaitingTheMainThreadHoldsThePoseShownUntilFramesArrive()
        {
            // The worker decodes while the game keeps rendering: no frame blocks, and every frame shows
            // either the pose held or a decoded one; the target still lands on its frame.
            using var loop = new FrameLoop(300, 0.25, Decoding.WorkerThread, seed: 7);
            loop.PlayUntil(1.0);
            var (root, rotations) = loop.ClipPose(2.5);
            loop.Player.RequestTransition(root, rotations, 0.5);
            double targetTime = loop.Time + 0.5;
            while (loop.Time + loop.NextStep < targetTime - 1e-9) loop.Step();
            loop.Step();
            loop.AssertShows(root, rotations, 1e-12);
            Assert.That(loop.Completions.Count, Is.EqualTo(1));
        }

        [Test]
        public void RequestsOutsideTheTrainedGapsAreWarnedAboutBeforeTheyRun()
        {
            // The component logs these warnings (MotionInbetweener.WarnOutsideTrainedRange); the player owns
            // the seconds → model frames conversion, so it answers what a request of that length becomes.
            using var loop = new FrameLoop(60, 0, Decoding.WorkerThread, seed: 13);
            using Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
            ModelContract c = model.Contract;
            (int nMin, int nMax) = c.TrainingMissingFrames;
            Assume.That(c.HasTrainingRanges && nMax > 0, "the tiny model states its trained gap lengths");
            double rate = loop.Player.FrameRate;
            ModelCheckReport inside = loop.Player.CheckRequest((nMax + 1) / rate);
            Assert.That(inside.CountOf(CheckSeverity.Warning) + inside.CountOf(CheckSeverity.Error), Is.EqualTo(0), string.Join("\n", inside));
            ModelCheckReport longer = loop.Player.CheckRequest((nMax + 2) / rate);
            Assert.That(longer.Where(x => x.Severity == CheckSeverity.Warning).Select(x => x.Message),
                Has.Some.Contains($"a gap of {nMax + 1} frames"), string.Join("\n", longer));
        }

        [Test]
        public void RequestsThatCannotBeServedSayWhy()
        {
            using var loop = new FrameLoop(60, 0, Decoding.WorkerThread, seed: 9);
            var (root, rotations) = loop.ClipPose(1.0);
            var early = Assert.Throws<InvalidOperationException>(() => loop.Player.RequestTransition(root, rotations, 0.5));
            Assert.That(early!.Message, Does.Contain("play at least one frame"));
            loop.PlayUntil(0.5);
            // The tiny model's largest frame index is 255: with P = 10 a transition spans at most 246 model frames.
            var tooLong = Assert.Throws<ArgumentOutOfRangeException>(() => loop.Player.RequestTransition(root, rotations, 9.0));
            Assert.That(tooLong!.Message, Does.Contain("this model spans at most 8.2 s"));
            Assert.Throws<ArgumentOutOfRangeException>(() => loop.Player.RequestTransition(root, rotations, 0));
            Assert.That(loop.Player.IsPlaying, Is.False);
            Assert.That(loop.Completions, Is.Empty);
        }

        private static double MaxDifference(double[] a, double[] b)
        {
            double max = 0;
            for (int i = 0; i < a.Length; i += 4)
            {
                max = Math.Max(max, RotationAssert.Distance(QuaternionD.Read(a, i), QuaternionD.Read(b, i)));
            }

            return max;
        }

        /// <summary>A character in a game loop: its clip, a player on the tiny model, and the frame clock.</summary>
        private sealed class FrameLoop : IDisposable
        {
            private readonly double _fps;
            private readonly double _jitter;
            private readonly TestRandom _random;
            private readonly SyntheticClip _clip;
            private readonly NamePoseConverter _map;
            private readonly TransitionScheduler _decoder;
            private readonly Inbetweener _reference;
            private ArrayPoseStream _stream;

            public FrameLoop(double fps, double jitter, Decoding decoding, int seed)
            {
                _fps = fps;
                _jitter = jitter;
                _random = new TestRandom(seed);
                Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);
                _decoder = decoding == Decoding.WorkerThread ? new WorkerThreadScheduler(model) : new MainThreadScheduler(model);
                _reference = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel);
                ModelContract c = model.Contract;
                // The character lists its bones in another order than the model: the map must reorder.
                var names = new List<string>(c.Skeleton.Names);
                names.Reverse();
                _map = new NamePoseConverter(c.Skeleton, c.UnitScale, names);
                _clip = new SyntheticClip(names.Count, seed);
                Player = new TransitionPlayer(_map, _decoder, new PlaybackSettings { BlendInSeconds = BlendIn, BlendOutSeconds = BlendOut, LockFeet = false });
                Player.TransitionCompleted += e => Completions.Add(e);
                _stream = new ArrayPoseStream(new double[3], new double[4 * names.Count]);
                Shown = new ArrayPoseStream(new double[3], new double[4 * names.Count]);
                NextStep = Draw();
                Time = -NextStep;
            }

            public TransitionPlayer Player { get; }

            public List<TransitionCompletion> Completions { get; } = new List<TransitionCompletion>();

            public double Time { get; private set; }

            /// <summary>The next frame's interval, drawn in advance so that a test can stop before the target frame.</summary>
            public double NextStep { get; private set; }

            /// <summary>What the last frame showed.</summary>
            public ArrayPoseStream Shown { get; }

            public (double[] Root, double[] Rotations) ClipPose(double time) => _clip.Pose(time);

            public void Step()
            {
                Time += NextStep;
                NextStep = Draw();
                // The controller's output this frame, then the player's layer on top of it.
                _clip.Sample(Time, _stream.Root, _stream.Rotations);
                _decoder.Pump();
                Player.Step(Time, ref _stream);
                Array.Copy(_stream.Root, Shown.Root, 3);
                Array.Copy(_stream.Rotations, Shown.Rotations, _stream.Rotations.Length);
                Assert.That(Player.ShownRotations.ToArray(), Is.EqualTo(Shown.Rotations));
            }

            public void PlayUntil(double time)
            {
                while (Time + NextStep <= time) Step();
            }

            public void AssertShowsClip()
            {
                var (root, rotations) = ClipPose(Time);
                AssertShows(root, rotations, 1e-12);
            }

            public void AssertShows(double[] root, double[] rotations, double tolerance)
            {
                RotationAssert.SameVector(Vector3D.Read(Shown.Root, 0), Vector3D.Read(root, 0), tolerance);
                for (int b = 0; b < _clip.BoneCount; b++)
                {
                    RotationAssert.SameRotation(QuaternionD.Read(Shown.Rotations, 4 * b), QuaternionD.Read(rotations, 4 * b), tolerance, $"bone {b} at t = {Time}");
                }
            }

            /// <summary>Key <paramref name="key"/> of the request equals a character pose converted to the model's space.</summary>
            public void AssertKeyIs(Transition keys, int key, double[] root, double[] rotations, double tolerance)
            {
                var modelRoot = new double[3];
                var modelRotations = new double[4 * _map.JointCount];
                _map.ToModel(root, rotations, modelRoot, modelRotations);
                RotationAssert.SameVector(Vector3D.Read(keys.KeyRootPositions, 3 * key), Vector3D.Read(modelRoot, 0), tolerance / 0.01);
                for (int j = 0; j < _map.JointCount; j++)
                {
                    RotationAssert.SameRotation(QuaternionD.Read(keys.KeyLocalRotations, 4 * (key * _map.JointCount + j)), QuaternionD.Read(modelRotations, 4 * j), tolerance, $"key {key} joint {j}");
                }
            }

            /// <summary>
            /// The Core in-betweener's answer to the same request, run separately (whole graph, its own
            /// instance): model frames 0 (last past key) .. G (target), in the model's space.
            /// </summary>
            public void ExpectedFrames(Transition keys, out double[][] roots, out double[][] rotations)
            {
                var t = new Transition(keys.Skeleton, keys.PastFrames, keys.MissingFrames);
                Array.Copy(keys.KeyRootPositions, t.KeyRootPositions, t.KeyRootPositions.Length);
                Array.Copy(keys.KeyLocalRotations, t.KeyLocalRotations, t.KeyLocalRotations.Length);
                _reference.Inbetween(t);
                int g = t.MissingFrames + 1;
                int jr = 4 * _map.JointCount;
                roots = new double[g + 1][];
                rotations = new double[g + 1][];
                for (int i = 0; i <= g; i++)
                {
                    bool key = i == 0 || i == g;
                    int k = i == 0 ? t.PastFrames - 1 : t.PastFrames;
                    roots[i] = new ArraySegment<double>(key ? t.KeyRootPositions : t.RootPositions, 3 * (key ? k : i - 1), 3).ToArray();
                    rotations[i] = new ArraySegment<double>(key ? t.KeyLocalRotations : t.LocalRotations, jr * (key ? k : i - 1), jr).ToArray();
                }
            }

            /// <summary>The frame shows the expected model frames at fractional model time <paramref name="u"/> (SLERP/LERP between the two around it).</summary>
            public void AssertShowsModelTime(double u, double[][] roots, double[][] rotations, double tolerance)
            {
                int a = Math.Min((int)Math.Floor(u), roots.Length - 2);
                double f = u - a;
                var root = new double[3];
                var modelRotations = new double[rotations[0].Length];
                for (int c = 0; c < 3; c++) root[c] = roots[a][c] + f * (roots[a + 1][c] - roots[a][c]);
                for (int j = 0; j < modelRotations.Length; j += 4)
                {
                    Quaternions.Normalize(Quaternions.Slerp(QuaternionD.Read(rotations[a], j), QuaternionD.Read(rotations[a + 1], j), f)).Write(modelRotations, j);
                }

                var characterRoot = new double[3];
                var characterRotations = new double[4 * _map.BoneCount];
                _map.ToCharacter(root, modelRotations, characterRoot, characterRotations);
                AssertShows(characterRoot, characterRotations, tolerance);
            }

            public void Dispose()
            {
                _decoder.Dispose();
                _reference.Dispose();
            }

            private double Draw() => (1.0 / _fps) * (1 + _jitter * _random.Uniform(-1, 1));
        }
    }
}
