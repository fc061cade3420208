using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.OnnxRuntime;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// A character's requests and recorded poses are refused before anything is built from them: a duration whose
    /// model frames overflow an int (1e8 s is 3e9 frames) is an error of the check and an out-of-range argument of
    /// the request, never a short gap or an OutOfMemoryException; a NaN or infinite target or recorded pose is refused
    /// (the request with an exception naming the argument; a shown pose with the status the component reports)
    /// instead of showing NaN for the whole transition (issue 31, items 10 and 16).
    /// </summary>
    [TestFixture]
    public sealed class NonFiniteAndOverlongRequestTests
    {
        private MainThreadScheduler _scheduler = null!;
        private NamePoseConverter _converter = null!;

        [SetUp]
        public void SetUp()
        {
            _scheduler = new MainThreadScheduler(OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true));
            ModelContract c = _scheduler.Contract;
            _converter = new NamePoseConverter(c.Skeleton, c.UnitScale, c.Skeleton.Names);
        }

        [TearDown]
        public void TearDown() => _scheduler.Dispose();

        [Test]
        public void CheckOfAHundredMillionSecondsReportsAnError()
        {
            TransitionPlayer player = PlayerWithHistory();
            ModelCheckReport report = player.CheckRequest(1e8);
            Assert.That(report.HasErrors, Is.True);
            Assert.That(report.FirstError!.Message, Does.Contain("3000000000 model frames"));
        }

        [Test]
        public void RequestOfAHundredMillionSecondsIsOutOfRange()
        {
            TransitionPlayer player = PlayerWithHistory();
            (double[] root, double[] rotations) = Pose();
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => player.RequestTransition(root, rotations, 1e8))!;
            Assert.That(e.ParamName, Is.EqualTo("durationSeconds"));
            Assert.That(player.IsPlaying, Is.False);
        }

        [Test]
        public void NonFiniteTargetIsRefusedNamingTheArgument()
        {
            TransitionPlayer player = PlayerWithHistory();
            (double[] root, double[] rotations) = Pose();
            rotations[4 * 3 + 1] = double.NaN;
            var e = Assert.Throws<ArgumentException>(() => player.RequestTransition(root, rotations, 0.5))!;
            Assert.That(e.ParamName, Is.EqualTo("targetRotations"));
            Assert.That(e.Message, Does.Contain("bone 3"));
            (root, rotations) = Pose();
            root[1] = double.PositiveInfinity;
            e = Assert.Throws<ArgumentException>(() => player.RequestTransition(root, rotations, 0.5))!;
            Assert.That(e.ParamName, Is.EqualTo("targetRoot"));
            Assert.That(player.IsPlaying, Is.False, "nothing was requested");
        }

        [Test]
        public void NaNRecordedFrameIsRefusedAndNotRecorded()
        {
            TransitionPlayer player = PlayerWithHistory();
            int count = player.History.Count;
            (double[] root, double[] rotations) = Pose();
            rotations[0] = double.NaN;
            var e = Assert.Throws<ArgumentException>(() => player.Record(1.0, root, rotations))!;
            Assert.That(e.ParamName, Is.EqualTo("shownRotations"));
            Assert.That(player.History.Count, Is.EqualTo(count));
        }

        [Test]
        public void NaNShownPoseStopsTheCharacterWithAReason()
        {
            var character = new TransitionCharacter(_converter, _scheduler, new PlaybackSettings(), RootFrame.Identity, "tiny", "ONNX Runtime");
            (double[] root, double[] rotations) = Pose();
            var shown = new double[character.PoseLength];
            root.CopyTo(shown, 0);
            rotations.CopyTo(shown, 3);
            var input = new CharacterFrameInput { Callback = FrameCallback.Update, ClockMode = AnimationClockMode.Scaled, DeltaTime = 1 / 60.0, UnscaledDeltaTime = 1 / 60.0, FixedDeltaTime = 0.02, Place = new CharacterPlace { RotationW = 1, Scale = 1 } };
            Assert.That(character.Frame(input, shown, default).Played, Is.True);
            shown[3 + 4 * 2] = double.NaN;
            CharacterFrameOutput frame = character.Frame(input, shown, default);
            Assert.That(frame.Played, Is.False);
            Assert.That(frame.Failed, Is.True);
            Assert.That(frame.FailureReason, Does.Contain("pose shown has bone 2's rotation value 0 = NaN; expected finite numbers"));
            Assert.That(character.Player.History.Count, Is.EqualTo(1), "only the finite pose was recorded");
        }

        private TransitionPlayer PlayerWithHistory()
        {
            var player = new TransitionPlayer(_converter, _scheduler);
            (double[] root, double[] rotations) = Pose();
            for (int f = 0; f < 30; f++) player.Record(f / 60.0, root, rotations);
            return player;
        }

        private (double[] Root, double[] Rotations) Pose()
        {
            var root = new double[] { 0, 90, 0 };
            var rotations = new double[4 * _converter.BoneCount];
            for (int b = 0; b < _converter.BoneCount; b++) rotations[4 * b] = 1;
            return (root, rotations);
        }
    }
}
