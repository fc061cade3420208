using DeltaInterpolator.Core.Characters;
using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Transitions in the space the controller's root motion uses, so that a character walks through a
    /// transition instead of sliding. With root motion off (<see cref="Enabled"/> false) the controller
    /// moves the root bone inside the character, which stays put: that space is the character's, and
    /// poses pass unchanged. With root motion on the controller keeps the root bone in place and moves the
    /// character (the Animator's transform) by the stream's velocity: poses are recorded and targets given
    /// in the world (anchored where the character first stood), the model's root trajectory is split into
    /// the character's motion (horizontal, as the velocity the Animator applies) and the root bone's
    /// position inside it.
    /// </summary>
    /// <remarks>
    /// <para>Each rendered frame, main thread, with the character's world frame (where the last frame was
    /// shown): <see cref="BeginFrame"/>; <see cref="ShownToMotionSpace"/> on the pose shown last frame
    /// before <see cref="TransitionPlayer.Record"/>, and <see cref="TargetToMotionSpace(Span{double}, Span{double})"/> on a target before
    /// <see cref="TransitionPlayer.RequestTransition"/>; after <see cref="TransitionPlayer.BeginFrame"/>,
    /// <see cref="Plan"/> turns the transition's pose back into the stream's space and gives the velocity
    /// (<see cref="TransitionVelocity"/>) that the animation job blends with the controller's
    /// (<see cref="BlendVelocity"/>).</para>
    /// <para>While the transition plays, the character follows the transition root's horizontal motion
    /// exactly once the blend-in is over (during it, the part of the controller's motion still shown is
    /// caught up smoothly). From the target frame on, the transition's pose moves on with the velocity it
    /// arrived with (with root motion on, it rides along with the character), while the weight hands the
    /// motion back to the controller; so the speed eases from the transition's to the controller's, with
    /// no stop at the target and no pop at the end of the blend-out.</para>
    /// <para>Positions are in Unity's space. Allocation-free; main thread only.</para>
    /// </remarks>
    public sealed class RootMotion
    {
        /// <summary>
        /// Seconds over which the character catches up with where the transition wants it after the
        /// blend-in (time constant of the pull); short enough to stand under the hips long before the
        /// target, long enough that the speed changes by a few percent per frame.
        /// </summary>
        public const double CatchUpSeconds = 0.25;

        private RootFrame _anchorToWorld;      // motion space (raw-bone coordinates of the anchored character) → world
        private RootFrame _toWorld;            // this frame's stream space → world (character frame · armature)
        private RootFrame _character;
        private bool _anchored;
        private int _request;
        private Vector3D _lastShownRoot;       // motion space
        private Vector3D _previousPoseRoot;    // motion space: the transition's root last frame
        private Vector3D _desired;             // world: where the transition wants the character now
        private Vector3D _arrivalVelocity;     // motion space, per second: the transition root's velocity at its target
        private Vector3D _carry;               // motion space: how far the target pose has moved on since it was reached
        private double _lastTime;
        private bool _wasReached;

        /// <summary>Creates the root motion of a character whose root bone's parent sits at <paramref name="armature"/> in the character.</summary>
        public RootMotion(RootFrame armature)
        {
            Armature = armature;
            _character = RootFrame.Identity;
            _toWorld = armature;
            _anchorToWorld = armature;
        }

        /// <summary>The root bone's parent in the character's space.</summary>
        public RootFrame Armature { get; }

        /// <summary>True when the Animator applies root motion (<c>Animator.applyRootMotion</c>); read every frame.</summary>
        public bool Enabled { get; set; }

        /// <summary>The character's frame in the world given to the last <see cref="BeginFrame"/> (where it stands now).</summary>
        public RootFrame CharacterFrame => _character;

        /// <summary>This frame's transition velocity (world, per second; zero with root motion off or when no transition plays).</summary>
        public Vector3D TransitionVelocity { get; private set; }

        /// <summary>
        /// Starts a frame: <paramref name="character"/> is the character's frame in the world (Unity: the
        /// Animator's transform position, rotation and uniform scale) as the last frame was shown. The first
        /// call anchors the motion space there.
        /// </summary>
        public void BeginFrame(RootFrame character)
        {
            _character = character;
            if (!Enabled)
            {
                _toWorld = Armature;
                _anchorToWorld = Armature;
                _anchored = false;
                return;
            }

            _toWorld = character.Then(Armature);
            if (!_anchored)
            {
                _anchorToWorld = _toWorld;
                _anchored = true;
            }
        }

        /// <summary>
        /// The pose shown last frame (root bone position and rotation, stream space, in place) into motion
        /// space, as <see cref="TransitionPlayer.Record"/> expects it; remembered as where a new request starts.
        /// </summary>
        public void ShownToMotionSpace(Span<double> rootPosition, Span<double> rootRotation)
        {
            TargetToMotionSpace(rootPosition, rootRotation);
            _lastShownRoot = Vector3D.Read(rootPosition, 0);
        }

        /// <summary>A pose given relative to where the character stands now (stream space) into motion space, in place.</summary>
        public void TargetToMotionSpace(Span<double> rootPosition, Span<double> rootRotation) => ToMotionSpace(_toWorld, rootPosition, rootRotation);

        /// <summary>
        /// A pose given relative to where the character stood at <paramref name="character"/> (an earlier frame
        /// of this motion space, e.g. when a deferred request was made; stream space) into motion space, in place.
        /// </summary>
        public void TargetToMotionSpace(RootFrame character, Span<double> rootPosition, Span<double> rootRotation) =>
            ToMotionSpace(Enabled ? character.Then(Armature) : Armature, rootPosition, rootRotation);

        private void ToMotionSpace(RootFrame toWorld, Span<double> rootPosition, Span<double> rootRotation)
        {
            Vector3D world = toWorld.PointToParent(Vector3D.Read(rootPosition, 0));
            _anchorToWorld.PointFromParent(world).Write(rootPosition, 0);
            QuaternionD q = toWorld.RotationToParent(QuaternionD.Read(rootRotation, 0));
            _anchorToWorld.RotationFromParent(q).Write(rootRotation, 0);
        }

        /// <summary>
        /// After <see cref="TransitionPlayer.BeginFrame"/>: this frame's transition velocity and the
        /// transition's root (position and rotation) in the stream's space, where the character will stand
        /// when the frame is shown.
        /// </summary>
        /// <param name="player">The character's player (its pose is in motion space).</param>
        /// <param name="time">This frame's time (seconds), as given to the player.</param>
        /// <param name="deltaTime">Seconds since the last frame (the animation's delta time).</param>
        /// <param name="controllerVelocity">The controller's root velocity (world, per second): this frame's, or the last known.</param>
        /// <param name="poseRoot">Receives the transition's root bone position (stream space, 3 values).</param>
        /// <param name="poseRootRotation">Receives the transition's root bone local rotation (stream space, 4 values).</param>
        public void Plan(TransitionPlayer player, double time, double deltaTime, Vector3D controllerVelocity, Span<double> poseRoot, Span<double> poseRootRotation)
        {
            if (player == null) throw new ArgumentNullException(nameof(player));
            if (player.CurrentRequestId != _request)
            {
                // A new request starts from the pose shown, with the character where it stands.
                _request = player.CurrentRequestId;
                _previousPoseRoot = _lastShownRoot;
                _desired = Horizontal(_character.Position);
                _carry = Vector3D.Zero;
                _arrivalVelocity = Vector3D.Zero;
                _wasReached = false;
                _lastTime = player.History.Count > 0 ? player.History.NewestTime : time;
            }

            Vector3D root = Vector3D.Read(player.PoseRoot, 0);
            Vector3D velocity = Vector3D.Zero;
            Vector3D shift = Vector3D.Zero;     // the character's displacement this frame (world)
            if (player.IsPlaying && deltaTime > 0)
            {
                bool reached = player.HasReachedTarget;
                bool ridingAlong = reached && _wasReached;
                if (!ridingAlong)
                {
                    // The transition root's horizontal motion since the last frame; on the target frame its
                    // velocity is measured up to the target time (the frame may come a little later).
                    double span = (reached ? player.TargetTime : time) - _lastTime;
                    Vector3D moved = HorizontalInMotion(root - _previousPoseRoot);
                    if (span > 1e-9) _arrivalVelocity = (1.0 / span) * moved;
                    _previousPoseRoot = root;
                    if (reached)
                    {
                        _wasReached = true;
                        _carry = Math.Max(0.0, time - player.TargetTime) * _arrivalVelocity;
                        moved = moved + _carry;
                    }

                    Vector3D behind = _desired - Horizontal(_character.Position);
                    Vector3D step = _anchorToWorld.VectorToParent(moved);
                    _desired = _desired + step;
                    // The transition root's velocity, plus a gentle pull toward where the transition wants
                    // the character: during the blend-in the controller's share of the velocity moved it
                    // elsewhere, and catching that up in one frame would jolt it.
                    velocity = (1.0 / deltaTime) * step + (1.0 / CatchUpSeconds) * behind;
                }
                else
                {
                    velocity = _anchorToWorld.VectorToParent(_arrivalVelocity);
                    if (!Enabled) _carry = _carry + deltaTime * _arrivalVelocity;
                }

                if (Enabled)
                {
                    shift = deltaTime * BlendVelocity(player.Weight, velocity, controllerVelocity);
                    // Past the target the pose rides along with the character, keeping its place in it.
                    if (ridingAlong) _carry = _carry + _anchorToWorld.VectorFromParent(shift);
                }
            }

            _lastTime = time;
            TransitionVelocity = Enabled ? velocity : Vector3D.Zero;
            RootFrame shownAt = Enabled ? new RootFrame(_character.Position + shift, _character.Rotation, _character.Scale).Then(Armature) : Armature;
            root = root + _carry;
            shownAt.PointFromParent(_anchorToWorld.PointToParent(root)).Write(poseRoot, 0);
            shownAt.RotationFromParent(_anchorToWorld.RotationToParent(QuaternionD.Read(player.PoseRotations, 0))).Write(poseRootRotation, 0);
        }

        /// <summary>
        /// The root velocity the animation job sets (world, per second): the transition's and the
        /// controller's blended by the transition's weight (0: the controller's alone).
        /// </summary>
        public static Vector3D BlendVelocity(double weight, Vector3D transitionVelocity, Vector3D controllerVelocity)
        {
            if (weight <= 0) return controllerVelocity;
            if (weight >= 1) return transitionVelocity;
            return controllerVelocity + weight * (transitionVelocity - controllerVelocity);
        }

        private static Vector3D Horizontal(Vector3D v) => new Vector3D(v.X, 0.0, v.Z);

        // A motion-space displacement without its vertical part (vertical in the world, or in the character
        // with root motion off: a rotated armature's own axes may have Z up).
        private Vector3D HorizontalInMotion(Vector3D v) => _anchorToWorld.VectorFromParent(Horizontal(_anchorToWorld.VectorToParent(v)));
    }
}
