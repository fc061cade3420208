using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// A humanoid character (not the model's rig: HumanBodyBones names, other bone axes, a turned and
    /// scaled armature, left-handed) walks in a simulated game loop and is sent to a pose 2 m ahead, with
    /// root motion on (the controller moves the character by a velocity, the root bone stays in place)
    /// and off (the controller moves the root bone inside a character that stays put). The loop does what
    /// the Unity component and its animation job do each frame, with <see cref="RootMotion"/> between the
    /// stream and <see cref="TransitionPlayer"/>, and what the Animator does after the job (apply the
    /// velocity, read in the character's frame as Unity's Kinematica writes it; <see cref="RootMotionFrameTests"/> covers
    /// an engine in the world's frame too). The transition plays the network's SLERP/LERP baseline (<see cref="PlaybackSettings.SlerpOnly"/>),
    /// so the root trajectory it follows is known; a last case runs the tiny network and checks arrival.
    /// </summary>
    [TestFixture]
    public sealed class RootMotionFrameLoopTests
    {
        private const double Distance = 2.0;       // metres, in the world
        private const double Duration = 1.0;       // seconds

        [TestCase(true, 2.0, 1.0, 60.0, 0.0, false)]
        [TestCase(true, 1.5, 1.0, 60.0, 0.0, false)]
        [TestCase(true, 2.0, 1.7, 144.0, 0.25, false)]
        [TestCase(true, 1.5, 0.6, 144.0, 0.25, false)]
        [TestCase(false, 2.0, 1.0, 60.0, 0.0, false)]
        [TestCase(false, 2.0, 1.7, 144.0, 0.25, false)]
        [TestCase(true, 2.0, 1.7, 144.0, 0.25, true)]
        [TestCase(false, 2.0, 1.7, 144.0, 0.25, true)]
        [TestCase(true, 1.5, 1.0, 30.0, 0.0, true)]
        public void WalksToATarget2MetresAheadArrivesOnItsFrameNeverBackwardNoJumpAtBlendOut(bool applyRootMotion, double speed, double characterScale, double fps, double jitter, bool sampledByTheGraph)
        {
            using var loop = new Loop(applyRootMotion, speed, characterScale, fps, jitter, slerpOnly: true);
            loop.PlayUntil(1.2);
            Vector3D start = loop.HipsWorld;
            Vector3D target = loop.RequestAhead(Distance, Duration, sampledByTheGraph);
            // A clip's pose sampled under root motion is in place: it stands where the controller's motion brings the character by
            // the arrival (speed × duration ahead); a pose given to the request stands where it was asked for (2 m ahead).
            double ahead = sampledByTheGraph && applyRootMotion ? speed * Duration : Distance;
            Assert.That(Horizontal(target - start).Length, Is.EqualTo(ahead).Within(0.05), "the target stands where it was asked for, or where the walk brings the character");
            double targetTime = loop.Time + Duration;

            double lastForward = loop.Forward(loop.HipsWorld);
            double lastSpeed = speed;
            double worstSpeedChange = 0, worstAt = 0;
            bool arrived = false;
            double end = targetTime + 0.2 + 0.3;
            while (loop.Time < end)
            {
                Vector3D before = loop.HipsWorld;
                Vector3D rootBefore = loop.Character.Position;
                loop.Step();
                double forward = loop.Forward(loop.HipsWorld);
                Assert.That(forward, Is.GreaterThanOrEqualTo(lastForward - 1e-9), $"moved backward at t = {loop.Time:F4}");
                lastForward = forward;
                if (applyRootMotion) Assert.That(loop.Forward(loop.Character.Position), Is.GreaterThanOrEqualTo(loop.Forward(rootBefore) - 1e-9), $"the character moved backward at t = {loop.Time:F4}");

                // The root's speed: the hips' horizontal speed in the world (the character's, with root motion on).
                Vector3D moved = applyRootMotion ? loop.Character.Position - rootBefore : Horizontal(loop.HipsWorld - before);
                double v = moved.Length / loop.LastStep;
                if (Math.Abs(v - lastSpeed) > worstSpeedChange)
                {
                    worstSpeedChange = Math.Abs(v - lastSpeed);
                    worstAt = loop.Time - (targetTime - Duration);
                }

                lastSpeed = v;

                if (loop.Completions.Count > 0 && !arrived)
                {
                    arrived = true;
                    Assert.That(loop.Time, Is.GreaterThanOrEqualTo(targetTime - 1e-9), "arrived early");
                    Assert.That(loop.Time - loop.LastStep, Is.LessThan(targetTime - 1e-9), "the first frame at or after the target time shows it");
                    Assert.That(loop.Completions[0].ReachedTarget, Is.True);
                    Assert.That(loop.Completions[0].RequestId, Is.EqualTo(loop.RequestId));
                    // On the target: at the target time exactly; a frame that comes later shows it moved on at the arrival speed.
                    double late = loop.Time - targetTime;
                    double miss = Horizontal(loop.HipsWorld - target).Length;
                    TestContext.WriteLine($"arrived at t = {loop.Time:F4} ({late * 1000:F2} ms after the target time), {miss * 1000:F3} mm from the target");
                    Assert.That(miss, Is.LessThanOrEqualTo(1e-6 + 1.05 * (Distance / Duration) * late));
                    Assert.That(Math.Abs(loop.HipsWorld.Y - target.Y), Is.LessThan(1e-6), "hips height on the target frame");
                }
            }

            Assert.That(arrived, Is.True, "the transition completed");
            Assert.That(loop.Player.IsPlaying, Is.False, "the blend-out ended");
            TestContext.WriteLine($"root motion {(applyRootMotion ? "on" : "off")}, controller {speed} m/s, scale {characterScale}: largest change of root speed between frames {worstSpeedChange:F4} m/s ({worstSpeedChange / speed:P1} of the controller's), {worstAt:F3} s after the request");
            Assert.That(worstSpeedChange, Is.LessThanOrEqualTo(0.2 * speed));
            // After the blend-out the controller's own motion shows, at its own speed.
            Assert.That(lastSpeed, Is.EqualTo(speed).Within(1e-6));
        }

        [TestCase(true)]
        [TestCase(false)]
        public void WithTheNetworkTheCharacterStillArrivesOnTheTargetFrame(bool applyRootMotion)
        {
            using var loop = new Loop(applyRootMotion, 2.0, 1.3, 60.0, 0.0, slerpOnly: false);
            loop.PlayUntil(1.2);
            Vector3D target = loop.RequestAhead(Distance, Duration);
            Assert.That(loop.Player.WaitUntilDecoded(10000), Is.True);
            while (loop.Completions.Count == 0) loop.Step();
            Assert.That(Horizontal(loop.HipsWorld - target).Length, Is.LessThan(1e-6 + 2.1 * (loop.Time - loop.Player.TargetTime)));
        }

        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void EachFrameOfATransitionWithRootMotionAllocatesNothing()
        {
            using var loop = new Loop(true, 1.5, 1.0, 60.0, 0.0, slerpOnly: true);
            loop.PlayUntil(1.2);
            loop.RequestAhead(Distance, Duration);
            loop.Step();
            long before = GC.GetAllocatedBytesForCurrentThread();
            // Through the transition, the target frame and the blend-out.
            for (int i = 0; i < 90; i++) loop.Step();
            long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.That(loop.Completions.Count, Is.EqualTo(1), "the loop crossed the target frame");
            Assert.That(bytes, Is.EqualTo(0), "bytes allocated by 90 frames (RootMotion, TransitionPlayer, PoseBlend, SkeletonPoseConverter)");
        }

        private static Vector3D Horizontal(Vector3D v) => new Vector3D(v.X, 0, v.Z);

        /// <summary>The game loop: controller, component (Update + animation job), Animator root motion.</summary>
        private sealed class Loop : IDisposable
        {
            private readonly bool _rootMotionOn;
            private readonly double _speed;
            private readonly double _fps;
            private readonly double _jitter;
            private readonly TestRandom _random;
            private readonly UnityHumanoid _humanoid;
            private readonly TransitionScheduler _scheduler;
            private readonly TransitionCharacter _character;
            private readonly double[] _shown;
            private readonly double _hipsHeight;
            private ArrayPoseStream _stream;
            private double _nextStep;
            private double[] _sampledTarget = new double[0];
            private bool _sampled;
            private Vector3D _appliedVelocity;    // what the Animator applied last frame (world)

            public Loop(bool applyRootMotion, double speed, double characterScale, double fps, double jitter, bool slerpOnly)
            {
                _rootMotionOn = applyRootMotion;
                _speed = speed;
                _fps = fps;
                _jitter = jitter;
                _random = new TestRandom(17);
                Inbetweener model = OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true);
                _scheduler = new MainThreadScheduler(model);
                _humanoid = UnityHumanoid.Model(model.Contract.Skeleton, UnityHumanoid.Blender, seed: 21);
                SkeletonPoseConverter map = _humanoid.Rig.CreatePoseConverter(model.Contract.Skeleton);
                _character = new TransitionCharacter(map, _scheduler, new PlaybackSettings { BlendInSeconds = 0.1, BlendOutSeconds = 0.2, SlerpOnly = slerpOnly }, map.Armature, "tiny", "ONNX Runtime");
                Player = _character.Player;
                Player.TransitionCompleted += e => Completions.Add(e);
                int n = _humanoid.BoneCount;
                _stream = new ArrayPoseStream(new double[3], new double[4 * n]);
                _hipsHeight = _humanoid.Armature.PointToParent(Vector3D.Read(_humanoid.Positions, 0)).Y;
                // The character stands turned 30° in the world, at its scale.
                Character = new RootFrame(new Vector3D(3.0, 0.0, -1.0), Quaternions.FromAxisAngle(Vector3D.UnitY, Math.PI / 6), characterScale);
                // The pose the engine shows before the first frame: the controller's (as the component reads the bones).
                _shown = new double[3 + 4 * n];
                Controller(0, _stream.Root, _stream.Rotations);
                _stream.Root.CopyTo(_shown, 0);
                _stream.Rotations.CopyTo(_shown, 3);
                _nextStep = Draw();
                Time = 0;
            }

            public TransitionPlayer Player { get; }

            public List<TransitionCompletion> Completions { get; } = new List<TransitionCompletion>(16);

            public double Time { get; private set; }

            public double LastStep { get; private set; }

            /// <summary>The Animator's transform in the world.</summary>
            public RootFrame Character { get; private set; }

            /// <summary>Where the hips were shown last frame, in the world.</summary>
            public Vector3D HipsWorld => Character.Then(_humanoid.Armature).PointToParent(Vector3D.Read(_shown, 0));

            /// <summary>Distance along the direction the character walks (its +Z in the world).</summary>
            public double Forward(Vector3D world) => Vector3D.Dot(world, Quaternions.Apply(Character.Rotation, Vector3D.UnitZ));

            public void PlayUntil(double time)
            {
                while (Time + _nextStep <= time) Step();
            }

            /// <summary>
            /// Requests the controller's pose a little later, its hips <paramref name="metres"/> ahead of the
            /// hips shown (in the world), sampled in the space the controller's root motion uses.
            /// </summary>
            /// <remarks>
            /// <paramref name="sampledByTheGraph"/>: as the component requests a clip's pose. The request is deferred
            /// (<see cref="TransitionPlayer.DeferTransition"/>) with where the character stands now; the next
            /// evaluation samples the clip through the playable graph (the job reads its input stream), and the
            /// Update after it completes the request in the root-motion space of the request's frame. With root motion on the
            /// engine samples the pose in place (its hips where the controller's are now, in the character), and the character
            /// places it where the controller's velocity brings it by the arrival (<paramref name="metres"/> does not apply).
            /// </remarks>
            public Vector3D RequestAhead(double metres, double seconds, bool sampledByTheGraph = false)
            {
                var root = new double[3];
                var rotations = new double[4 * _humanoid.BoneCount];
                Controller(Time + 0.37, root, rotations);
                Vector3D shownInCharacter = _humanoid.Armature.PointToParent(Vector3D.Read(_shown, 0));
                bool inPlace = sampledByTheGraph && _rootMotionOn;
                Vector3D targetInCharacter = new Vector3D(shownInCharacter.X, _hipsHeight, shownInCharacter.Z + (inPlace ? 0 : metres / Character.Scale));
                _humanoid.Armature.PointFromParent(targetInCharacter).Write(root, 0);
                RootFrame arrivalPlace = inPlace ? new RootFrame(Character.Position + seconds * _speed * Quaternions.Apply(Character.Rotation, Vector3D.UnitZ), Character.Rotation, Character.Scale) : Character;
                Vector3D world = arrivalPlace.Then(_humanoid.Armature).PointToParent(Vector3D.Read(root, 0));
                // As the component does: the pose shown and where the character stands now, then the request.
                _character.Showed(Place(Character), _rootMotionOn, _shown);
                if (sampledByTheGraph)
                {
                    RequestId = _character.DeferTransition(seconds);
                    _sampledTarget = new double[3 + rotations.Length];
                    root.CopyTo(_sampledTarget, 0);
                    rotations.CopyTo(_sampledTarget, 3);
                    _sampled = false;
                    return world;
                }

                RequestId = _character.RequestTransition(root, rotations, seconds);
                return world;
            }

            /// <summary>The id of the last request.</summary>
            public int RequestId { get; private set; }

            public void Step()
            {
                double dt = _nextStep;
                Time += dt;
                LastStep = dt;
                _nextStep = Draw();
                // On the stream, the controller's velocity is in the character's frame.
                Vector3D controllerVelocity = _rootMotionOn ? _speed * Vector3D.UnitZ : Vector3D.Zero;

                // The frame's owner pumps the scheduler; then MotionInbetweener.Update: what Unity read, one call.
                _scheduler.Pump();
                var input = new CharacterFrameInput
                {
                    Callback = FrameCallback.Update,
                    ClockMode = AnimationClockMode.Scaled,
                    DeltaTime = dt,
                    UnscaledDeltaTime = dt,
                    FixedDeltaTime = 0.02,
                    ApplyRootMotion = _rootMotionOn,
                    Place = Place(Character),
                    ControllerVelocityX = controllerVelocity.X,
                    ControllerVelocityY = controllerVelocity.Y,
                    ControllerVelocityZ = controllerVelocity.Z,
                    AppliedVelocityX = _appliedVelocity.X,
                    AppliedVelocityY = _appliedVelocity.Y,
                    AppliedVelocityZ = _appliedVelocity.Z,
                };
                CharacterFrameOutput frame = _character.Frame(input, _shown, _sampled ? _sampledTarget : ReadOnlySpan<double>.Empty);
                // Every step advances the clock: each one plays (NUnit's Assert would allocate, so a plain check).
                if (!frame.Played) throw new InvalidOperationException("a frame step did not play: " + frame.FailureReason);

                // The Animator Controller's output, then TransitionLayerJob: root motion, then the pose (and the
                // target reader's job reads a requested clip's pose from its input stream).
                if (Player.HasDeferredTransition) _sampled = true;
                Controller(Time, _stream.Root, _stream.Rotations);
                var transitionVelocity = new Vector3D(frame.RootVelocityX, frame.RootVelocityY, frame.RootVelocityZ);
                Vector3D velocity = frame.RootMotion ? RootMotion.BlendVelocity(frame.Weight, transitionVelocity, controllerVelocity) : controllerVelocity;
                var pose = new ReadOnlySpan<double>(frame.Pose);
                var shown = new Span<double>(_shown);
                PoseBlend.Apply(ref _stream, frame.Weight, pose.Slice(0, 3), pose.Slice(3), shown.Slice(0, 3), shown.Slice(3));

                // The Animator applies root motion after the job (only when applyRootMotion is on), turning the stream's
                // velocity from the character's frame into the world.
                _appliedVelocity = Quaternions.Apply(Character.Rotation, velocity);
                if (_rootMotionOn) Character = new RootFrame(Character.Position + dt * _appliedVelocity, Character.Rotation, Character.Scale);
            }

            private static CharacterPlace Place(RootFrame f) => new CharacterPlace
            {
                X = f.Position.X, Y = f.Position.Y, Z = f.Position.Z,
                RotationW = f.Rotation.W, RotationX = f.Rotation.X, RotationY = f.Rotation.Y, RotationZ = f.Rotation.Z,
                Scale = f.Scale,
            };

            public void Dispose() => _scheduler.Dispose();

            /// <summary>
            /// The controller walking at the set speed: with root motion on, in place (the velocity moves the
            /// character); off, the hips move forward inside the character. Bones sway around the T-pose.
            /// </summary>
            private void Controller(double time, double[] root, double[] rotations)
            {
                double forward = _rootMotionOn ? 0.0 : _speed * time / Character.Scale;
                var hips = new Vector3D(0.0, _hipsHeight + 0.01 * Math.Sin(4 * Math.PI * time), forward);
                _humanoid.Armature.PointFromParent(hips).Write(root, 0);
                for (int b = 0; b < _humanoid.BoneCount; b++)
                {
                    QuaternionD rest = QuaternionD.Read(_humanoid.ReferenceRotations, 4 * b);
                    var axis = new Vector3D(Math.Sin(b), Math.Cos(b), 0.5);
                    QuaternionD sway = Quaternions.FromAxisAngle((1.0 / axis.Length) * axis, 0.15 * Math.Sin(2 * Math.PI * 1.3 * time + b));
                    Quaternions.Normalize(Quaternions.Multiply(rest, sway)).Write(rotations, 4 * b);
                }
            }

            private double Draw() => (1.0 / _fps) * (1 + _jitter * _random.Uniform(-1, 1));
        }
    }
}
