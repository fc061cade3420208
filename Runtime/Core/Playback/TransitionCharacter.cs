using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Scheduling;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// One character's frame, in the order the game runs it: its clock (<see cref="AnimationClock"/>), the pose the
    /// engine showed last into the history, a deferred target that the engine has sampled, the transition's pose and
    /// weight for the frame (<see cref="TransitionPlayer"/>: scheduling, SLERP → network ease-in, foot locking,
    /// conversion to the character) and the root motion that moves the character along it (<see cref="RootMotion"/>).
    /// An engine gathers what it read into a <see cref="CharacterFrameInput"/>, makes one <see cref="Frame"/> call and
    /// writes the <see cref="CharacterFrameOutput"/> into its animation job; before a request it hands over the pose it
    /// showed (<see cref="Showed"/>). The frame-loop tests drive this type, so they test the frame the game runs.
    /// </summary>
    /// <remarks>
    /// <para>The scheduler's pump is not part of a character's frame: the frame's owner pumps once per rendered frame
    /// for every character (<see cref="TransitionScheduler.Pump"/>).</para>
    /// <para>Pose buffers hold the root position (3 values) then bones × 4 rotation values (w, x, y, z), in the
    /// stream's space. Main thread only; <see cref="Frame"/> allocates nothing.</para>
    /// </remarks>
    public sealed class TransitionCharacter
    {
        private readonly AnimationClock _clock = new AnimationClock();
        private readonly PlaybackStatus _status = new PlaybackStatus();
        private readonly string _model;
        private readonly string _engine;
        private readonly int _poseLength;
        private readonly double[] _pose;
        private readonly double[] _recordRoot = new double[3];
        private readonly double[] _recordRotations;
        private readonly double[] _targetRoot = new double[3];
        private readonly double[] _targetRotations;
        private RootFrame _deferredFrame;
        private Vector3D _controllerVelocity;     // the controller's root velocity last read (world, per second; zero with root motion off)
        private StateTarget _sample;
        private int _sampleId;
        private StateTarget _handOff;
        private int _handOffId;
        private double _shownTime;
        private bool _shownPending;
        private QuaternionD _evaluatedRotation;   // the character's rotation when the engine evaluated the last frame played
        private bool _evaluatedUnblended;         // the last frame played let the controller's root velocity through unchanged

        /// <summary>Creates a character whose first pose shown is the one the engine shows before its first frame.</summary>
        /// <param name="converter">The character's bones ↔ the model's joints.</param>
        /// <param name="scheduler">Where the network runs (shared by the characters of one model).</param>
        /// <param name="settings">Blend times, past frames, foot locking; read at each request and frame.</param>
        /// <param name="armature">The root bone's parent in the character's space (<see cref="CharacterRig.Armature"/>).</param>
        /// <param name="modelName">The model's name, for failure messages.</param>
        /// <param name="engineName">The inference engine's name, for failure messages.</param>
        public TransitionCharacter(IPoseConverter converter, TransitionScheduler scheduler, PlaybackSettings settings, RootFrame armature, string modelName, string engineName)
        {
            Player = new TransitionPlayer(converter, scheduler, settings);
            RootMotion = new RootMotion(armature);
            Transitions = new AnimatorTransitions(this);
            _model = modelName ?? throw new ArgumentNullException(nameof(modelName));
            _engine = engineName ?? throw new ArgumentNullException(nameof(engineName));
            int bones = converter.BoneCount;
            _poseLength = 3 + 4 * bones;
            _pose = new double[_poseLength];
            _recordRotations = new double[4 * bones];
            _targetRotations = new double[4 * bones];
            _status.Run();
            // The pose the engine shows before the first frame is the first one recorded, so a request may follow at once.
            _shownTime = _clock.Time;
            _shownPending = true;
        }

        /// <summary>The character's transitions (history, requests, events).</summary>
        public TransitionPlayer Player { get; }

        /// <summary>The character's root motion (the space its poses and targets are in).</summary>
        public RootMotion RootMotion { get; }

        /// <summary>Which frame the engine's stream velocity is in, decided from what the engine applied (see <see cref="RootMotionFrameCheck"/>).</summary>
        public RootMotionFrameCheck RootMotionFrame { get; } = new RootMotionFrameCheck();

        /// <summary>The character's neural Animator transitions (off until a layer is watched): the controller's own transitions it replaces, fed each frame by <see cref="CharacterFrameInput.Layers"/>.</summary>
        public AnimatorTransitions Transitions { get; }

        /// <summary>The character's clock (the Animator's update mode).</summary>
        public AnimationClock Clock => _clock;

        /// <summary>Values per pose buffer: 3 + 4 × bones.</summary>
        public int PoseLength => _poseLength;

        /// <summary>
        /// The engine showed <paramref name="shownPose"/> (the animation job's output since the last frame) with the
        /// character at <paramref name="place"/>: it goes into the history once, in the root-motion space of where the
        /// character stands now. <see cref="Frame"/> does this itself; call it before a request made between frames.
        /// </summary>
        public void Showed(in CharacterPlace place, bool applyRootMotion, ReadOnlySpan<double> shownPose)
        {
            RootMotion.Enabled = applyRootMotion;
            RootMotion.BeginFrame(place.ToFrame());
            if (!_shownPending) return;
            if (shownPose.Length != _poseLength) throw new ArgumentException($"a shown pose has {_poseLength} values (3 + 4 × bones), not {shownPose.Length}", nameof(shownPose));
            _shownPending = false;
            shownPose.Slice(0, 3).CopyTo(_recordRoot);
            shownPose.Slice(3).CopyTo(_recordRotations);
            RootMotion.ShownToMotionSpace(_recordRoot, new Span<double>(_recordRotations, 0, 4));
            Player.Record(_shownTime, _recordRoot, _recordRotations);
        }

        /// <summary>
        /// One frame callback: advances the clock (nothing more when this callback does not drive it), records the pose
        /// shown, starts a deferred request whose target the engine sampled (<paramref name="sampledTarget"/>: a pose
        /// buffer, or empty), computes the transition's pose and weight and plans the root motion.
        /// </summary>
        /// <param name="input">What the engine read.</param>
        /// <param name="shownPose">The pose the engine showed last (the animation job's output).</param>
        /// <param name="sampledTarget">A deferred request's target as the engine sampled it (relative to where the character stood at the request), or empty.</param>
        public CharacterFrameOutput Frame(in CharacterFrameInput input, ReadOnlySpan<double> shownPose, ReadOnlySpan<double> sampledTarget)
        {
            var output = new CharacterFrameOutput { Pose = _pose };
            _clock.Mode = input.ClockMode;
            if (!_clock.Advance(input.Callback, input.DeltaTime, input.UnscaledDeltaTime, input.FixedDeltaTime)) return output;
            // Where the character stands now is where the last frame was shown (the engine applied its root motion since).
            if (_shownPending && shownPose.Length == _poseLength)
            {
                // A NaN the engine showed would become the keys of every later request: the character stops, and says why.
                string? broken = RequestChecks.NonFinite(shownPose.Slice(0, 3), shownPose.Slice(3), "pose shown");
                if (broken != null)
                {
                    _status.Fail(broken + " (the Animator Controller or a script wrote it); fix the animation, then enable the component again");
                    return Failure(output);
                }
            }

            Showed(input.Place, input.ApplyRootMotion, shownPose);
            // The controller's motion now, in the world: where a deferred target is placed (see PlaceDeferredTarget).
            var streamVelocity = new Vector3D(input.ControllerVelocityX, input.ControllerVelocityY, input.ControllerVelocityZ);
            _controllerVelocity = input.ApplyRootMotion ? RootMotionFrame.ToWorld(streamVelocity, RootMotion.CharacterFrame.Rotation) : Vector3D.Zero;
            if (sampledTarget.Length == _poseLength && Player.HasDeferredTransition) StartSampledTarget(sampledTarget);
            // After a sampled target started: a transition the controller starts now defers its own, which the next frame's sample starts.
            if (input.Layers != null && Transitions.Observe(new ReadOnlySpan<AnimatorLayerState>(input.Layers, 0, Math.Min(input.LayerCount, input.Layers.Length)), out StateTarget next))
            {
                _sample = next;
                _sampleId = Player.DeferredRequestId;
            }

            double time = _clock.Time;
            if (!_status.TryBeginFrame(Player, time, _model, _engine)) return Failure(output);

            // The stream's velocity is in a frame the engine does not name: while nothing blended it last frame, what the
            // engine applied in the world says which (RootMotionFrameCheck); the plan works in the world.
            if (input.ApplyRootMotion && _evaluatedUnblended)
                output.RootMotionWarning = RootMotionFrame.Observe(streamVelocity, new Vector3D(input.AppliedVelocityX, input.AppliedVelocityY, input.AppliedVelocityZ), _evaluatedRotation);
            QuaternionD rotation = RootMotion.CharacterFrame.Rotation;
            Span<double> pose = _pose;
            Player.PoseRoot.CopyTo(pose.Slice(0, 3));
            Player.PoseRotations.CopyTo(pose.Slice(3));
            RootMotion.Plan(Player, time, _clock.LastStep, RootMotionFrame.ToWorld(streamVelocity, rotation), pose.Slice(0, 3), pose.Slice(3, 4));
            Vector3D velocity = RootMotionFrame.ToStream(RootMotion.TransitionVelocity, rotation);
            output.Played = true;
            output.Weight = Player.Weight;
            output.RootVelocityX = velocity.X;
            output.RootVelocityY = velocity.Y;
            output.RootVelocityZ = velocity.Z;
            output.RootMotion = RootMotion.Enabled;
            _evaluatedRotation = rotation;
            _evaluatedUnblended = Player.Weight <= 0;
            output.SampleState = _sampleId != 0 && Player.DeferredRequestId == _sampleId;
            output.Sample = output.SampleState ? _sample : default;
            if (_handOffId != 0 && Player.LetGoArrivedId == _handOffId)
            {
                // The frame may come after the arrival time: the state plays on from where it is at this frame's time.
                output.PlayState = true;
                output.Play = _handOff.At(_handOff.Seconds + Math.Max(0, Player.LetGoLateSeconds));
                _handOffId = 0;
            }

            _shownTime = time;
            _shownPending = true;
            return output;
        }

        /// <summary>
        /// A transition to <paramref name="targetRoot"/>, <paramref name="targetRotations"/> (stream space, relative to
        /// where the character stands now: call <see cref="Showed"/> first) arriving in <paramref name="seconds"/>.
        /// </summary>
        /// <returns>The request's id, as <see cref="TransitionPlayer.TransitionCompleted"/> reports it.</returns>
        /// <exception cref="ArgumentOutOfRangeException">The duration is not positive, not finite, or longer than the model spans.</exception>
        /// <exception cref="ArgumentException">The target holds a value that is not finite.</exception>
        public int RequestTransition(ReadOnlySpan<double> targetRoot, ReadOnlySpan<double> targetRotations, double seconds)
        {
            if (targetRoot.Length < 3 || targetRotations.Length < _targetRotations.Length) throw new ArgumentException($"a target pose needs 3 root values and {_targetRotations.Length} rotation values");
            targetRoot.Slice(0, 3).CopyTo(_targetRoot);
            targetRotations.Slice(0, _targetRotations.Length).CopyTo(_targetRotations);
            RootMotion.TargetToMotionSpace(_targetRoot, new Span<double>(_targetRotations, 0, 4));
            return Player.RequestTransition(_targetRoot, _targetRotations, seconds);
        }

        /// <summary>
        /// A transition whose target the engine samples later (Unity: a clip through the playable graph); it arrives
        /// <paramref name="seconds"/> from now, placed where the character stands now (call <see cref="Showed"/> first) or, with
        /// root motion on, where the controller's root velocity now brings it by then (a walking character walks on through it
        /// rather than being pulled back). <see cref="Frame"/> starts it when the sampled target comes.
        /// </summary>
        public int DeferTransition(double seconds)
        {
            int id = Player.DeferTransition(seconds);
            PlaceDeferredTarget(seconds);
            return id;
        }

        /// <summary>
        /// <see cref="DeferTransition"/> as a hand-off (<see cref="TransitionPlayer.DeferHandOff"/>): from the pose shown at full weight,
        /// weight 0 from the frame it arrives, when the controller shows the target itself.
        /// </summary>
        public int DeferHandOff(double seconds)
        {
            int id = Player.DeferHandOff(seconds);
            PlaceDeferredTarget(seconds);
            return id;
        }

        /// <summary>
        /// A hand-off into a state of the controller: a transition to <paramref name="state"/>'s pose at its time
        /// (<see cref="StateTarget.Seconds"/>), arriving in <paramref name="seconds"/>. The engine samples that pose off-scene
        /// (<see cref="CharacterFrameOutput.SampleState"/> says which, in every frame until the pose comes back as the sampled target);
        /// in the frame it arrives the layer lets go (weight 0, no blend-out) and <see cref="CharacterFrameOutput.PlayState"/> tells
        /// the engine to put the controller in the state at that time (Unity: <c>Animator.PlayInFixedTime</c>), so the state plays on.
        /// Call <see cref="Showed"/> first, as for every request.
        /// </summary>
        /// <remarks>
        /// Pose and clip requests (<see cref="RequestTransition"/>, <see cref="DeferTransition"/>) visit their target and blend
        /// back out to whatever the controller plays over <see cref="PlaybackSettings.BlendOutSeconds"/>; only a hand-off changes what
        /// the controller plays.
        /// </remarks>
        /// <param name="state">The state, its layer and its time at arrival.</param>
        /// <param name="seconds">Seconds until arrival.</param>
        /// <param name="controller">What the engine knows of its controller's layers and states.</param>
        /// <returns>The request's id, as <see cref="TransitionPlayer.TransitionCompleted"/> reports it.</returns>
        /// <exception cref="ArgumentNullException"><paramref name="controller"/> is null.</exception>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="state"/>'s layer is not a layer of the controller (ParamName <c>state</c>), or <paramref name="seconds"/> is not positive, not finite or longer than the model spans (ParamName <c>durationSeconds</c>).</exception>
        /// <exception cref="ArgumentException">The controller has no such state on that layer (ParamName <c>state</c>).</exception>
        public int RequestState(in StateTarget state, double seconds, IControllerStates controller)
        {
            if (controller == null) throw new ArgumentNullException(nameof(controller));
            int layers = controller.LayerCount;
            if (state.Layer >= layers) throw new ArgumentOutOfRangeException(nameof(state), state.Layer, $"layer {state.Layer} is not a layer of the Animator Controller; expected a layer index in 0..{layers - 1}");
            if (!controller.HasState(state.Layer, state.StateHash)) throw new ArgumentException($"the Animator Controller has no state of hash {state.StateHash} on layer {state.Layer}; expected the hash of a state's name or full path on that layer (Animator.StringToHash)", nameof(state));
            int id = DeferHandOff(seconds);
            _sample = state;
            _sampleId = id;
            _handOff = state;
            _handOffId = id;
            return id;
        }

        /// <summary>Ends the current transition at once.</summary>
        public void Cancel() => Player.Cancel();

        private CharacterFrameOutput Failure(CharacterFrameOutput output)
        {
            output.Failed = _status.State == PlaybackState.Failed;
            output.FailureReason = output.Failed ? _status.Reason : null;
            output.Error = _status.Error;
            return output;
        }

        // Where a deferred target (a clip's or a state's pose, which the engine samples in place: its root relative to the
        // character) will stand: with root motion on, the character does not stay where it stands at the request but moves on
        // with the controller's root motion, so the target is placed where that motion (its velocity now, on the ground) brings
        // it by the arrival. Placed at the request's spot instead, a walking character would be pulled back to it and stop.
        private void PlaceDeferredTarget(double seconds)
        {
            RootFrame now = RootMotion.CharacterFrame;
            if (!RootMotion.Enabled)
            {
                _deferredFrame = now;
                return;
            }

            var ahead = new Vector3D(seconds * _controllerVelocity.X, 0.0, seconds * _controllerVelocity.Z);
            _deferredFrame = new RootFrame(now.Position + ahead, now.Rotation, now.Scale);
        }

        private void StartSampledTarget(ReadOnlySpan<double> sampled)
        {
            sampled.Slice(0, 3).CopyTo(_targetRoot);
            sampled.Slice(3).CopyTo(_targetRotations);
            RootMotion.TargetToMotionSpace(_deferredFrame, _targetRoot, new Span<double>(_targetRotations, 0, 4));
            Player.CompleteDeferredTransition(_targetRoot, _targetRotations);
        }
    }
}
