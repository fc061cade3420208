using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Tests.Playback;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// One character of a simulated game loop, driven the way MotionInbetweener drives it: what the engine read goes
    /// into one <see cref="TransitionCharacter.Frame"/> call, the controller's pose is written, and the frame's pose
    /// is blended over it into the pose shown (the animation job's output), which the next frame hands back. Root
    /// motion is off and the character stands at the world's origin, so the stream's space is the character's, unless
    /// <see cref="PlayWithRootMotion"/> turns it on: then the controller moves the character by a velocity, and this type
    /// does what the Animator does after the job (applies the stream's velocity, read in the engine's frame).
    /// </summary>
    /// <remarks>
    /// The frame's owner pumps the scheduler (once per rendered frame for every character), not this type. Requests
    /// hand over the pose shown first (<see cref="TransitionCharacter.Showed"/>), as the component does. A frame
    /// allocates nothing, so crowds of these measure the steady state.
    /// </remarks>
    public sealed class PlayingCharacter
    {
        /// <summary>Where the character stands: the world's origin, unrotated, unscaled.</summary>
        private static readonly CharacterPlace Origin = new CharacterPlace { RotationW = 1, Scale = 1 };

        private readonly TransitionCharacter _character;
        private readonly Action<double, double[], double[]> _controller;
        private readonly double[] _shownPose;
        private readonly double[] _sampledTarget;
        private ArrayPoseStream _stream;
        private bool _sampled;
        private CharacterPlace _place = Origin;
        private bool _rootMotion;
        private RootVelocityFrame _engineFrame;
        private Vector3D _controllerVelocity;     // the controller's root motion, in the character's frame
        private QuaternionD _appliedTurn = QuaternionD.Identity;
        private double _engineScale = 1.0;
        private Vector3D _streamVelocity;         // what the job read off the stream last frame
        private Vector3D _appliedVelocity;        // what the Animator applied last frame (world)

        /// <param name="converter">The character's bones ↔ the model's joints.</param>
        /// <param name="scheduler">The scheduler the frame's owner pumps.</param>
        /// <param name="settings">The character's playback settings.</param>
        /// <param name="controller">The controller's pose at a time (its own animation): (time, root, rotations).</param>
        public PlayingCharacter(IPoseConverter converter, TransitionScheduler scheduler, PlaybackSettings settings, Action<double, double[], double[]> controller)
        {
            _controller = controller;
            _character = new TransitionCharacter(converter, scheduler, settings, RootFrame.Identity, "tiny", "ONNX Runtime");
            int bones = converter.BoneCount;
            _stream = new ArrayPoseStream(new double[3], new double[4 * bones]);
            Shown = new ArrayPoseStream(new double[3], new double[4 * bones]);
            _shownPose = new double[_character.PoseLength];
            _sampledTarget = new double[_character.PoseLength];
            // The pose the engine shows before the first frame: the controller's at time 0.
            controller(0, Shown.Root, Shown.Rotations);
        }

        /// <summary>The character's transitions (history, requests, events, the frame's pose and weight).</summary>
        public TransitionPlayer Player => _character.Player;

        /// <summary>The character's clock: the time of its last frame.</summary>
        public double Time => _character.Clock.Time;

        /// <summary>What the last frame showed (the animation job's output).</summary>
        public ArrayPoseStream Shown { get; }

        /// <summary>The character (for hand-offs and its Animator transitions).</summary>
        public TransitionCharacter Character => _character;

        /// <summary>The controller layers' state machines the next frame hands in (as the glue reads them), or null.</summary>
        public AnimatorLayerState[]? Layers { get; set; }

        /// <summary>Entries of <see cref="Layers"/> filled.</summary>
        public int LayerCount { get; set; }

        /// <summary>Bones a masked controller layer above drives, kept from the controller's pose (<see cref="PoseBlend.ApplyMasked"/>), or null.</summary>
        public bool[]? KeptBones { get; set; }

        /// <summary>
        /// Called in each frame after the character's frame and before the controller's pose is taken: the glue's part that acts on the
        /// frame's instructions to the controller (<see cref="CharacterFrameOutput.PlayState"/>).
        /// </summary>
        public Action<CharacterFrameOutput>? BeforeController { get; set; }

        /// <summary>
        /// With root motion on, the controller's root velocity of each evaluation (its own frame, per second), read after it
        /// evaluates, instead of the constant one given to <see cref="PlayWithRootMotion"/>; null: that constant.
        /// </summary>
        public Func<Vector3D>? ControllerVelocity { get; set; }

        /// <summary>The last frame's output (its pose buffer is the character's).</summary>
        public CharacterFrameOutput LastFrame { get; private set; }

        /// <summary>Where the character stands in the world (moved by root motion after <see cref="PlayWithRootMotion"/>).</summary>
        public RootFrame Place => _place.ToFrame();

        /// <summary>The character's decision of the stream velocity's frame.</summary>
        public RootMotionFrameCheck RootMotionFrame => _character.RootMotionFrame;

        /// <summary>The root-motion warnings the frames gave (each frame's <see cref="CharacterFrameOutput.RootMotionWarning"/>), in order.</summary>
        public System.Collections.Generic.List<string> RootMotionWarnings { get; } = new System.Collections.Generic.List<string>();

        /// <summary>
        /// Root motion on from the next frame: the character stands at <paramref name="place"/>, the controller keeps its
        /// root bone in place and moves the character at <paramref name="controllerVelocity"/> (its own frame, per second);
        /// the engine puts the velocity on the stream in <paramref name="engineFrame"/> and applies it in that frame.
        /// <paramref name="appliedTurnDegrees"/> turns what it applies about the vertical, as a script changing root
        /// motion after the controller would (0: none); <paramref name="engineScale"/> multiplies it, as an engine scaling
        /// root motion with the character would (1: none).
        /// </summary>
        public void PlayWithRootMotion(RootFrame place, Vector3D controllerVelocity, RootVelocityFrame engineFrame, double appliedTurnDegrees = 0, double engineScale = 1)
        {
            _engineScale = engineScale;
            _place = PlaceOf(place);
            _rootMotion = true;
            _controllerVelocity = controllerVelocity;
            _engineFrame = engineFrame;
            _appliedTurn = Quaternions.FromAxisAngle(Vector3D.UnitY, appliedTurnDegrees * Math.PI / 180.0);
        }

        /// <summary>
        /// One rendered frame <paramref name="deltaTime"/> seconds after the last: the character's frame, the
        /// controller's pose at the new time, the transition blended over it into <see cref="Shown"/>.
        /// </summary>
        public CharacterFrameOutput Frame(double deltaTime)
        {
            var input = new CharacterFrameInput
            {
                Callback = FrameCallback.Update,
                ClockMode = AnimationClockMode.Scaled,
                DeltaTime = deltaTime,
                UnscaledDeltaTime = deltaTime,
                FixedDeltaTime = 0.02,
                ApplyRootMotion = _rootMotion,
                Place = _place,
                ControllerVelocityX = _streamVelocity.X, ControllerVelocityY = _streamVelocity.Y, ControllerVelocityZ = _streamVelocity.Z,
                AppliedVelocityX = _appliedVelocity.X, AppliedVelocityY = _appliedVelocity.Y, AppliedVelocityZ = _appliedVelocity.Z,
                Layers = Layers,
                LayerCount = LayerCount,
            };
            CharacterFrameOutput frame = _character.Frame(input, ShownPose(), _sampled ? _sampledTarget : ReadOnlySpan<double>.Empty);
            _sampled = false;
            // A plain check (NUnit's Assert would allocate): every frame here advances the clock and plays.
            if (!frame.Played) throw new InvalidOperationException("a frame did not play: " + frame.FailureReason, frame.Error);
            if (frame.RootMotionWarning != null) RootMotionWarnings.Add(frame.RootMotionWarning);
            BeforeController?.Invoke(frame);
            _controller(Time, _stream.Root, _stream.Rotations);
            if (ControllerVelocity != null) _controllerVelocity = ControllerVelocity();
            var pose = new ReadOnlySpan<double>(frame.Pose);
            PoseBlend.ApplyMasked(ref _stream, frame.Weight, pose.Slice(0, 3), pose.Slice(3), KeptBones, Shown.Root, Shown.Rotations);
            if (_rootMotion) ApplyRootMotion(frame, deltaTime);
            LastFrame = frame;
            return frame;
        }

        // The job's ProcessRootMotion (the controller's velocity on the stream, the transition's blended over it), then
        // the Animator moving the character by the stream's velocity, read in the engine's frame.
        private void ApplyRootMotion(in CharacterFrameOutput frame, double deltaTime)
        {
            RootFrame place = _place.ToFrame();
            bool local = _engineFrame == RootVelocityFrame.Local;
            Vector3D controller = local ? _controllerVelocity : Quaternions.Apply(place.Rotation, _controllerVelocity);
            var transition = new Vector3D(frame.RootVelocityX, frame.RootVelocityY, frame.RootVelocityZ);
            Vector3D stream = frame.RootMotion ? RootMotion.BlendVelocity(frame.Weight, transition, controller) : controller;
            Vector3D applied = _engineScale * Quaternions.Apply(_appliedTurn, local ? Quaternions.Apply(place.Rotation, stream) : stream);
            _place = PlaceOf(new RootFrame(place.Position + deltaTime * applied, place.Rotation, place.Scale));
            _streamVelocity = controller;
            _appliedVelocity = applied;
        }

        private static CharacterPlace PlaceOf(RootFrame f) => new CharacterPlace
        {
            X = f.Position.X, Y = f.Position.Y, Z = f.Position.Z,
            RotationW = f.Rotation.W, RotationX = f.Rotation.X, RotationY = f.Rotation.Y, RotationZ = f.Rotation.Z,
            Scale = f.Scale,
        };

        /// <summary>A hand-off into a controller state, from the pose shown, as the component requests one.</summary>
        public int RequestState(in StateTarget state, double seconds, IControllerStates controller)
        {
            _character.Showed(_place, _rootMotion, ShownPose());
            return _character.RequestState(state, seconds, controller);
        }

        /// <summary>A transition to a pose given in the character's space, from the pose shown, as the component requests one.</summary>
        public int RequestTransition(ReadOnlySpan<double> targetRoot, ReadOnlySpan<double> targetRotations, double seconds)
        {
            _character.Showed(_place, _rootMotion, ShownPose());
            return _character.RequestTransition(targetRoot, targetRotations, seconds);
        }

        /// <summary>A transition whose target the engine samples later (<see cref="Sampled"/>), as the component requests a clip's pose.</summary>
        public int DeferTransition(double seconds)
        {
            _character.Showed(_place, _rootMotion, ShownPose());
            return _character.DeferTransition(seconds);
        }

        /// <summary>The engine sampled a deferred request's target: the next <see cref="Frame"/> starts it.</summary>
        public void Sampled(double[] targetRoot, double[] targetRotations)
        {
            targetRoot.CopyTo(_sampledTarget, 0);
            targetRotations.CopyTo(_sampledTarget, 3);
            _sampled = true;
        }

        private double[] ShownPose()
        {
            Shown.Root.CopyTo(_shownPose, 0);
            Shown.Rotations.CopyTo(_shownPose, 3);
            return _shownPose;
        }
    }
}
