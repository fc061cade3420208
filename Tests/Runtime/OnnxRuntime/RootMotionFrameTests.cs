using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// The frame of the stream's root velocity (Unity's <c>AnimationStream.velocity</c>, whose C# source names none):
    /// a character turned 90° walks with root motion on while the engine puts its velocity on the stream in the
    /// character's frame (what Unity's Kinematica writes) or in the world's, frame by frame (<see cref="PlayingCharacter"/>
    /// simulates the Animator applying it), scaling it or not. In each, the run-time check (<see cref="RootMotionFrameCheck"/>)
    /// picks the engine's frame and scale before the request, and the character then travels toward its target, not sideways.
    /// </summary>
    [TestFixture]
    public sealed class RootMotionFrameTests
    {
        private const double Fps = 60.0;
        private const double Speed = 1.2;          // the controller's walk, m/s
        private const double Ahead = 2.0;          // metres
        private const double Seconds = 1.0;

        [TestCase(RootVelocityFrame.Local, 1.0)]
        [TestCase(RootVelocityFrame.World, 1.0)]
        [TestCase(RootVelocityFrame.Local, 1.7)]
        [TestCase(RootVelocityFrame.World, 0.6)]
        public void ACharacterTurned90DegreesTravelsTowardItsTargetInEitherEngineFrame(RootVelocityFrame engine, double engineScale)
        {
            using var loop = new Loop(engine, 0.0, engineScale);
            loop.PlayUntil(1.0);
            Assert.That(loop.Character.RootMotionFrame.Decided, Is.True, "five frames walking turned 90° decide the frame");
            Assert.That(loop.Character.RootMotionFrame.Frame, Is.EqualTo(engine));
            Assert.That(loop.Character.RootMotionFrame.Scale, Is.EqualTo(engineScale).Within(1e-9));
            Assert.That(loop.Character.RootMotionWarnings, Is.Empty);

            RootFrame start = loop.Character.Place;
            Vector3D forward = Quaternions.Apply(start.Rotation, Vector3D.UnitZ);
            Assert.That(forward.X, Is.EqualTo(1.0).Within(1e-9), "turned 90°: the character walks along the world's +X");
            Vector3D target = loop.RequestAhead();
            double targetTime = loop.Character.Time + Seconds;
            Vector3D side = Vector3D.Cross(Vector3D.UnitY, forward);

            double lastDistance = Horizontal(target - start.Position).Length, worstSideways = 0;
            bool arrived = false;
            while (loop.Character.Time < targetTime + 0.5)
            {
                loop.Step();
                Vector3D at = loop.Character.Place.Position;
                worstSideways = Math.Max(worstSideways, Math.Abs(Vector3D.Dot(at - start.Position, side)));
                if (!arrived)
                {
                    double distance = Horizontal(target - at).Length;
                    Assert.That(distance, Is.LessThanOrEqualTo(lastDistance + 1e-9), $"the character moved away from its target at t = {loop.Character.Time:F3}");
                    lastDistance = distance;
                }

                if (loop.Completions.Count > 0 && !arrived)
                {
                    arrived = true;
                    double late = loop.Character.Time - targetTime;
                    double miss = Horizontal(loop.HipsWorld - target).Length;
                    TestContext.WriteLine($"engine frame {engine}: arrived {late * 1000:F1} ms after the target time, hips {miss * 1000:F1} mm from the target");
                    Assert.That(miss, Is.LessThanOrEqualTo(0.01 + 1.1 * (Ahead / Seconds) * late), "the hips reach the target");
                }
            }

            Assert.That(arrived, Is.True, "the transition completed");
            TestContext.WriteLine($"engine frame {engine}: the character strayed at most {worstSideways * 1000:F1} mm sideways");
            Assert.That(worstSideways, Is.LessThan(0.05), "the character travels toward its target, not sideways");
        }

        [Test]
        public void UnderTheOtherFrameTheSameCharacterIsPushedSideways()
        {
            // What the package did before the check: the stream's velocity taken as the world's, against an engine that
            // writes it in the character's frame (as Kinematica does).
            using var loop = new Loop(RootVelocityFrame.Local, 0.0);
            loop.Character.RootMotionFrame.Assume(RootVelocityFrame.World);
            loop.PlayUntil(1.0);
            RootFrame start = loop.Character.Place;
            Vector3D side = Vector3D.Cross(Vector3D.UnitY, Quaternions.Apply(start.Rotation, Vector3D.UnitZ));
            loop.RequestAhead();
            double worstSideways = 0;
            for (int i = 0; i < 60; i++)
            {
                loop.Step();
                worstSideways = Math.Max(worstSideways, Math.Abs(Vector3D.Dot(loop.Character.Place.Position - start.Position, side)));
            }

            TestContext.WriteLine($"with the world frame assumed against a local engine: {worstSideways:F2} m sideways");
            Assert.That(worstSideways, Is.GreaterThan(0.3), "the wrong frame pushes the character sideways (the test above can fail)");
        }

        [Test]
        public void WhenNeitherFrameMatchesTheCharacterSaysSoOnce()
        {
            // A script turning root motion by 45° after the controller: neither the character's frame nor the world's matches.
            using var loop = new Loop(RootVelocityFrame.Local, 45.0);
            loop.PlayUntil(3.0);
            Assert.That(loop.Character.RootMotionWarnings, Has.Count.EqualTo(1));
            TestContext.WriteLine(loop.Character.RootMotionWarnings[0]);
            Assert.That(loop.Character.RootMotionWarnings[0], Does.StartWith("root motion: "));
            Assert.That(loop.Character.RootMotionFrame.Decided, Is.False);
            Assert.That(loop.Character.RootMotionFrame.Frame, Is.EqualTo(RootVelocityFrame.Local), "the evidence-backed default stays");
        }

        private static Vector3D Horizontal(Vector3D v) => new Vector3D(v.X, 0, v.Z);

        private sealed class Loop : IDisposable
        {
            private readonly SyntheticClip _clip;
            private readonly TransitionScheduler _scheduler;

            public Loop(RootVelocityFrame engine, double appliedTurnDegrees, double engineScale = 1.0)
            {
                Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);
                _scheduler = new MainThreadScheduler(model);
                ModelContract c = model.Contract;
                var map = new NamePoseConverter(c.Skeleton, c.UnitScale, c.Skeleton.Names);
                _clip = new SyntheticClip(c.JointCount, 5);
                Character = new PlayingCharacter(map, _scheduler, new PlaybackSettings { BlendInSeconds = 0.1, BlendOutSeconds = 0.2, SlerpOnly = true }, InPlace);
                Character.Player.TransitionCompleted += e => Completions.Add(e);
                var turned = new RootFrame(new Vector3D(3.0, 0.0, -1.0), Quaternions.FromAxisAngle(Vector3D.UnitY, Math.PI / 2), 1.0);
                Character.PlayWithRootMotion(turned, new Vector3D(0, 0, Speed), engine, appliedTurnDegrees, engineScale);
            }

            public PlayingCharacter Character { get; }

            public List<TransitionCompletion> Completions { get; } = new List<TransitionCompletion>();

            /// <summary>Where the hips were shown last frame, in the world.</summary>
            public Vector3D HipsWorld => Character.Place.PointToParent(new Vector3D(Character.Shown.Root[0], Character.Shown.Root[1], Character.Shown.Root[2]));

            /// <summary>The clip's pose a little later, its hips <see cref="Ahead"/> metres ahead of where the character stands; its world position.</summary>
            public Vector3D RequestAhead()
            {
                var (root, rotations) = _clip.Pose(Character.Time + 0.4);
                root[0] = 0;
                root[2] = Ahead;
                Vector3D world = Character.Place.PointToParent(Vector3D.Read(root, 0));
                Character.RequestTransition(root, rotations, Seconds);
                return world;
            }

            public void Step()
            {
                _scheduler.Pump();
                Character.Frame(1.0 / Fps);
            }

            public void PlayUntil(double time)
            {
                while (Character.Time + 1.0 / Fps <= time + 1e-9) Step();
            }

            public void Dispose() => _scheduler.Dispose();

            // The controller with root motion: the clip in place (the velocity moves the character).
            private void InPlace(double time, double[] root, double[] rotations)
            {
                _clip.Sample(time, root, rotations);
                root[0] = 0;
                root[2] = 0;
            }
        }
    }
}
