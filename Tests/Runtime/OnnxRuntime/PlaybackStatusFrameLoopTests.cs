using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using System.Threading;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// What the component does around its player, in a simulated game loop on the real ONNX Runtime with the
    /// tiny fixture: the transition's time follows the Animator's update mode (<see cref="AnimationClock"/>:
    /// a paused Normal-mode character freezes, an UnscaledTime one keeps playing, a Fixed one steps with
    /// physics), it waits without error until its settings arrive, and an inference engine that fails while
    /// playing stops it once with a message naming the model and what to do (<see cref="PlaybackStatus"/>),
    /// instead of leaving it silently idle. The failing engine is the real backend behind a wrapper that
    /// throws from Run after a number of runs.
    /// </summary>
    [TestFixture]
    public sealed class PlaybackStatusFrameLoopTests
    {
        private const string ModelName = "tiny-model";
        private const string EngineName = "ONNX Runtime";

        public enum Decoding
        {
            WorkerThread,
            MainThread,
        }

        [TestCase(Decoding.WorkerThread)]
        [TestCase(Decoding.MainThread)]
        public void AnEngineFailureWhilePlayingStopsOnceWithTheModelAndWhatToDo(Decoding decoding)
        {
            // Two runs succeed (the request's keys and a first frame run), the next throws.
            using var loop = new Loop(AnimationClockMode.Scaled, decoding, runsBeforeFailure: 2);
            loop.Status.Run();
            loop.PlayFrames(30, 1.0 / 60);
            var (root, rotations) = loop.ClipPose(3.0);
            int id = loop.Request(root, rotations, 0.5);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.False, "the engine fails before the transition is decoded");

            int failures = 0;
            for (int frame = 0; frame < 60; frame++)
            {
                bool wasRunning = loop.Status.IsRunning;
                loop.Frame(1.0 / 60, 1.0 / 60);
                if (wasRunning && !loop.Status.IsRunning) failures++;
            }

            Assert.That(failures, Is.EqualTo(1), "the failure is reported once");
            Assert.That(loop.Status.State, Is.EqualTo(PlaybackState.Failed));
            Assert.That(loop.Status.Reason, Does.Contain("'" + ModelName + "'").And.Contain(EngineName).And.Contain(Loop.EngineMessage).And.Contain("enable the component again"));
            Assert.That(loop.Status.Error, Is.InstanceOf<InferenceFailedException>());
            Assert.That(loop.Status.Error!.InnerException!.Message, Is.EqualTo(Loop.EngineMessage));
            Assert.That(loop.Player.IsPlaying, Is.False);
            // The request still completes once (not reached), so a game waiting for it is not left hanging.
            Assert.That(loop.Completions.Count, Is.EqualTo(1));
            Assert.That(loop.Completions[0].RequestId, Is.EqualTo(id));
            Assert.That(loop.Completions[0].ReachedTarget, Is.False);
            // Frames after the failure do not touch the player: the character shows its own animation.
            Assert.That(loop.PlayedFrames, Is.EqualTo(30 + loop.FramesBeforeFailure));
        }

        [Test]
        public void ItWaitsWithoutErrorUntilItsSettingsArriveThenPlays()
        {
            // AddComponent, then settings assigned: the first frames find nothing to build and must not fail.
            using var loop = new Loop(AnimationClockMode.Scaled, Decoding.MainThread, runsBeforeFailure: int.MaxValue);
            loop.Status.Wait("no settings asset is assigned");
            loop.PlayFrames(10, 1.0 / 60);
            Assert.That(loop.Status.State, Is.EqualTo(PlaybackState.Waiting));
            Assert.That(loop.PlayedFrames, Is.EqualTo(0));

            loop.Status.Run();
            loop.PlayFrames(20, 1.0 / 60);
            var (root, rotations) = loop.ClipPose(2.0);
            loop.Request(root, rotations, 0.3);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);
            loop.PlayFrames(40, 1.0 / 60);
            Assert.That(loop.Completions.Count, Is.EqualTo(1));
            Assert.That(loop.Completions[0].ReachedTarget, Is.True);
            Assert.That(loop.Status.IsRunning, Is.True);
        }

        [Test]
        public void BlendTimesEditedWhilePlayingApplyWithoutARebuild()
        {
            // The component copies edited blend times into the PlaybackSettings its player holds (no rebuild, the
            // transition keeps playing); with blend-out edited to 0 the controller takes over on the next frame.
            using var loop = new Loop(AnimationClockMode.Scaled, Decoding.MainThread, runsBeforeFailure: int.MaxValue);
            loop.Status.Run();
            loop.PlayFrames(30, 1.0 / 60);
            var (root, rotations) = loop.ClipPose(3.0);
            loop.Request(root, rotations, 0.3);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);
            loop.PlayFrames(6, 1.0 / 60);
            loop.Settings.BlendOutSeconds = 0;
            while (loop.Completions.Count == 0) loop.Frame(1.0 / 60, 1.0 / 60);
            Assert.That(loop.Player.Weight, Is.EqualTo(1.0), "the target frame shows the target");
            loop.Frame(1.0 / 60, 1.0 / 60);
            Assert.That(loop.Player.IsPlaying, Is.False);
            Assert.That(loop.Player.Weight, Is.EqualTo(0.0));
        }

        [Test]
        public void WhilePausedANormalCharacterFreezesAndAnUnscaledOneKeepsPlaying()
        {
            using var normal = new Loop(AnimationClockMode.Scaled, Decoding.MainThread, runsBeforeFailure: int.MaxValue);
            using var unscaled = new Loop(AnimationClockMode.Unscaled, Decoding.MainThread, runsBeforeFailure: int.MaxValue);
            foreach (Loop loop in new[] { normal, unscaled })
            {
                loop.Status.Run();
                loop.PlayFrames(30, 1.0 / 60);
                var (root, rotations) = loop.ClipPose(3.0);
                loop.Request(root, rotations, 0.5);
                Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);
                loop.PlayFrames(12, 1.0 / 60);
                Assert.That(loop.Player.Weight, Is.EqualTo(1.0));
            }

            // Time.timeScale = 0 for two seconds: deltaTime 0, unscaledDeltaTime 1/60.
            double[] frozen = (double[])normal.Shown.Rotations.Clone();
            double frozenAt = normal.Clock.Time;
            for (int frame = 0; frame < 120; frame++)
            {
                normal.Frame(0, 1.0 / 60);
                unscaled.Frame(0, 1.0 / 60);
                Assert.That(normal.Shown.Rotations, Is.EqualTo(frozen), $"paused frame {frame}");
            }

            Assert.That(normal.Clock.Time, Is.EqualTo(frozenAt));
            Assert.That(normal.Player.IsPlaying, Is.True);
            Assert.That(normal.Completions, Is.Empty);
            Assert.That(unscaled.Completions.Count, Is.EqualTo(1));
            Assert.That(unscaled.Completions[0].ReachedTarget, Is.True);

            // Unpaused, the Normal character finishes the rest of its transition in scaled time.
            int resumed = 0;
            while (normal.Completions.Count == 0 && resumed < 60)
            {
                normal.Frame(1.0 / 60, 1.0 / 60);
                resumed++;
            }

            Assert.That(resumed, Is.EqualTo(18).Within(1), "0.3 s of the 0.5 s transition were left");
            Assert.That(normal.Completions.Count, Is.EqualTo(1));
            Assert.That(normal.Completions[0].ReachedTarget, Is.True);
            Assert.That(normal.Completions[0].Time, Is.EqualTo(normal.Clock.Time));
        }

        [Test]
        public void AFixedModeCharacterAdvancesWithPhysicsStepsOnly()
        {
            // Rendered at 60 fps with Time.fixedDeltaTime 0.02: 0, 1 or 2 physics steps per rendered frame.
            using var loop = new Loop(AnimationClockMode.Fixed, Decoding.MainThread, runsBeforeFailure: int.MaxValue);
            loop.Status.Run();
            double physicsDue = 0;
            double realTime = 0;
            void RenderFrame()
            {
                realTime += 1.0 / 60;
                while (physicsDue + 0.02 <= realTime + 1e-12)
                {
                    physicsDue += 0.02;
                    loop.Frame(0.02, 0.02, FrameCallback.FixedUpdate);
                }

                loop.Frame(1.0 / 60, 1.0 / 60);
            }

            for (int i = 0; i < 60; i++) RenderFrame();
            Assert.That(loop.Clock.Time, Is.EqualTo(physicsDue).Within(1e-9));
            Assert.That(loop.PlayedFrames, Is.EqualTo(50), "one played frame per physics step, none per rendered frame");
            var (root, rotations) = loop.ClipPose(3.0);
            double requestedAt = loop.Clock.Time;
            loop.Request(root, rotations, 0.5);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);
            while (loop.Completions.Count == 0 && realTime < 5) RenderFrame();
            Assert.That(loop.Completions.Count, Is.EqualTo(1));
            Assert.That(loop.Completions[0].ReachedTarget, Is.True);
            Assert.That(loop.Completions[0].Time - requestedAt, Is.EqualTo(0.5).Within(1e-9), "arrives on the physics step at the requested time");
        }

        /// <summary>A character in a game loop on the tiny model, with the component's clock and status.</summary>
        private sealed class Loop : IDisposable
        {
            public const string EngineMessage = "simulated GPU worker failure";
            private readonly SyntheticClip _clip;
            private readonly TransitionScheduler _decoder;
            private readonly RunBudget _budget;
            private readonly TransitionCharacter _character;
            private readonly double[] _shown;
            private ArrayPoseStream _stream;

            public Loop(AnimationClockMode mode, Decoding decoding, int runsBeforeFailure)
            {
                _budget = new RunBudget();
                string whole = Fixtures.TinyModel;
                var inbetweener = new Inbetweener(
                    new FailingBackend(OnnxRuntimeBackend.Load(whole), _budget),
                    new FailingBackend(OnnxRuntimeBackend.Load(whole.Replace(".onnx", ".keys.onnx")), _budget),
                    new FailingBackend(OnnxRuntimeBackend.Load(whole.Replace(".onnx", ".frame.onnx")), _budget));
                // Loading probes each graph once; the budget counts the runs of play only.
                _budget.Arm(runsBeforeFailure);
                _decoder = decoding == Decoding.WorkerThread ? new WorkerThreadScheduler(inbetweener) : new MainThreadScheduler(inbetweener);
                ModelContract c = inbetweener.Contract;
                var map = new NamePoseConverter(c.Skeleton, c.UnitScale, c.Skeleton.Names);
                _clip = new SyntheticClip(c.Skeleton.JointCount, seed: 11);
                Settings = new PlaybackSettings { BlendInSeconds = 0.1, BlendOutSeconds = 0.2 };
                _mode = mode;
                _character = new TransitionCharacter(map, _decoder, Settings, RootFrame.Identity, ModelName, EngineName);
                Player.TransitionCompleted += e => Completions.Add(e);
                _stream = new ArrayPoseStream(new double[3], new double[4 * c.Skeleton.JointCount]);
                Shown = new ArrayPoseStream(new double[3], new double[4 * c.Skeleton.JointCount]);
                // The pose shown before the first frame: the clip's at time 0.
                _clip.Sample(0, Shown.Root, Shown.Rotations);
                _shown = new double[_character.PoseLength];
            }

            public TransitionPlayer Player => _character.Player;

            private readonly AnimationClockMode _mode;

            /// <summary>The settings the player reads at each frame (the component edits them in place).</summary>
            public PlaybackSettings Settings { get; }

            public AnimationClock Clock => _character.Clock;

            public PlaybackStatus Status { get; } = new PlaybackStatus();

            public List<TransitionCompletion> Completions { get; } = new List<TransitionCompletion>();

            public ArrayPoseStream Shown { get; }

            /// <summary>Frames the player played (its BeginFrame returned).</summary>
            public int PlayedFrames { get; private set; }

            /// <summary>Frames played after the request before the one that failed.</summary>
            public int FramesBeforeFailure { get; private set; }

            public (double[] Root, double[] Rotations) ClipPose(double time)
            {
                var root = new double[3];
                var rotations = new double[4 * _clip.BoneCount];
                _clip.Sample(time, root, rotations);
                return (root, rotations);
            }

            public void PlayFrames(int frames, double deltaTime)
            {
                for (int i = 0; i < frames; i++) Frame(deltaTime, deltaTime);
            }

            /// <summary>
            /// One engine callback, as the component handles it: the clock decides whether this callback
            /// plays a frame and by how much time advances; the controller's clip runs on the same clock.
            /// </summary>
            public void Frame(double deltaTime, double unscaledDeltaTime, FrameCallback callback = FrameCallback.Update)
            {
                // The frame's owner pumps the scheduler once; a component that is not running has no character to call.
                _decoder.Pump();
                if (!Status.IsRunning)
                {
                    // Not running: the character shows its own animation.
                    _clip.Sample(Clock.Time, Shown.Root, Shown.Rotations);
                    return;
                }

                var input = new CharacterFrameInput
                {
                    Callback = callback, ClockMode = _mode, DeltaTime = deltaTime, UnscaledDeltaTime = unscaledDeltaTime, FixedDeltaTime = 0.02,
                    Place = new CharacterPlace { RotationW = 1, Scale = 1 },
                };
                CharacterFrameOutput frame = _character.Frame(input, ShownPose(), ReadOnlySpan<double>.Empty);
                if (frame.Failed)
                {
                    // The component: one failure, with the character's reason; then its own animation.
                    Status.Fail(frame.FailureReason!, frame.Error);
                    _clip.Sample(Clock.Time, Shown.Root, Shown.Rotations);
                    return;
                }

                if (!frame.Played) return;
                PlayedFrames++;
                if (Player.IsPlaying) FramesBeforeFailure++;
                _clip.Sample(Clock.Time, _stream.Root, _stream.Rotations);
                var pose = new ReadOnlySpan<double>(frame.Pose);
                PoseBlend.Apply(ref _stream, frame.Weight, pose.Slice(0, 3), pose.Slice(3), Shown.Root, Shown.Rotations);
            }

            /// <summary>A request as the component makes it: the pose shown handed over first, then the target.</summary>
            public int Request(double[] root, double[] rotations, double seconds)
            {
                _character.Showed(new CharacterPlace { RotationW = 1, Scale = 1 }, false, ShownPose());
                return _character.RequestTransition(root, rotations, seconds);
            }

            private double[] ShownPose()
            {
                Shown.Root.CopyTo(_shown, 0);
                Shown.Rotations.CopyTo(_shown, 3);
                return _shown;
            }

            public void Dispose() => _decoder.Dispose();
        }

        private sealed class RunBudget
        {
            private int _left = int.MaxValue;

            public void Arm(int runs) => _left = runs;

            /// <summary>True while runs are left (thread-safe: the worker thread runs the graphs).</summary>
            public bool Take() => _left == int.MaxValue || Interlocked.Decrement(ref _left) >= 0;
        }

        /// <summary>A real backend whose runs throw once the shared budget is spent (a GPU worker that dies mid-game).</summary>
        private sealed class FailingBackend : IInferenceBackend
        {
            private readonly IInferenceBackend _inner;
            private readonly RunBudget _budget;

            public FailingBackend(IInferenceBackend inner, RunBudget budget)
            {
                _inner = inner;
                _budget = budget;
            }

            public ModelDescription Description => _inner.Description;

            public IInferenceBinding Bind(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs) => new Binding(_inner.Bind(inputs, outputs), _budget);

            public void Dispose() => _inner.Dispose();

            private sealed class Binding : IInferenceBinding
            {
                private readonly IInferenceBinding _inner;
                private readonly RunBudget _budget;

                public Binding(IInferenceBinding inner, RunBudget budget)
                {
                    _inner = inner;
                    _budget = budget;
                }

                public void Run()
                {
                    if (!_budget.Take()) throw new InvalidOperationException(Loop.EngineMessage);
                    _inner.Run();
                }

                public void Dispose() => _inner.Dispose();
            }
        }
    }
}
