using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Where the engine shows the character: its frame in the world (Unity: the Animator's transform position,
    /// rotation and uniform scale), as plain values the engine reads.
    /// </summary>
    public struct CharacterPlace
    {
        /// <summary>Position in the world (x, y, z).</summary>
        public double X, Y, Z;

        /// <summary>Rotation in the world (w, x, y, z).</summary>
        public double RotationW, RotationX, RotationY, RotationZ;

        /// <summary>Uniform scale (Unity: <c>lossyScale.x</c>).</summary>
        public double Scale;

        /// <summary>The place as a <see cref="RootFrame"/>.</summary>
        /// <exception cref="ArgumentOutOfRangeException">The scale is not a positive finite number.</exception>
        public RootFrame ToFrame() => new RootFrame(new Vector3D(X, Y, Z), new QuaternionD(RotationW, RotationX, RotationY, RotationZ), Scale);
    }

    /// <summary>What the engine read for one frame callback of a character, as plain values (no engine type).</summary>
    public struct CharacterFrameInput
    {
        /// <summary>Which callback this is (rendered frame or physics step).</summary>
        public FrameCallback Callback;

        /// <summary>The Animator's clock (Unity: <c>Animator.updateMode</c>).</summary>
        public AnimationClockMode ClockMode;

        /// <summary>Seconds since the last callback: scaled, unscaled and the physics step (Unity: <c>Time</c>).</summary>
        public double DeltaTime, UnscaledDeltaTime, FixedDeltaTime;

        /// <summary>True when the Animator applies root motion (<c>Animator.applyRootMotion</c>).</summary>
        public bool ApplyRootMotion;

        /// <summary>Where the character stands now (the engine applied last frame's root motion since).</summary>
        public CharacterPlace Place;

        /// <summary>The controller's own root velocity last frame (world, per second), as the animation job read it.</summary>
        public double ControllerVelocityX, ControllerVelocityY, ControllerVelocityZ;

        /// <summary>
        /// The watched controller layers' state machines as the engine read them (its own buffer, the first <see cref="LayerCount"/>
        /// entries), for <see cref="TransitionCharacter.Transitions"/>; null: no neural Animator transitions.
        /// </summary>
        public AnimatorLayerState[]? Layers;

        /// <summary>Entries of <see cref="Layers"/> filled this frame.</summary>
        public int LayerCount;
    }

    /// <summary>
    /// What one frame of a <see cref="TransitionCharacter"/> gives the engine: the transition's pose and weight to blend
    /// over the controller's output, and the root velocity to blend over its root motion. Plain values and the
    /// character's own pose buffer, so a binder copies it into the animation job as it is.
    /// </summary>
    /// <remarks>
    /// Instructions to the engine's controller ride here too: a state pose to sample off-scene (<see cref="SampleState"/>) and,
    /// in the frame a hand-off arrives, the state to play (<see cref="PlayState"/>). A Timeline clip's weight would be one more
    /// field, written by the character and copied by the binder.
    /// </remarks>
    public struct CharacterFrameOutput
    {
        /// <summary>True when this callback advanced the character's clock and computed a frame; false: leave the job as it is.</summary>
        public bool Played;

        /// <summary>True when the inference engine failed in this frame (<see cref="FailureReason"/> says what to do).</summary>
        public bool Failed;

        /// <summary>The failure's message (model, engine, what it said, what to do); null unless <see cref="Failed"/>.</summary>
        public string? FailureReason;

        /// <summary>The engine's exception; null unless <see cref="Failed"/>.</summary>
        public Exception? Error;

        /// <summary>The transition's weight this frame (0: the controller's pose, 1: the transition's).</summary>
        public double Weight;

        /// <summary>The transition's pose in the stream's space: root position (3) then bones × 4 rotations (w x y z). The character's buffer: copy it, do not keep it.</summary>
        public double[] Pose;

        /// <summary>The transition's root velocity (world, per second; zero with root motion off).</summary>
        public double RootVelocityX, RootVelocityY, RootVelocityZ;

        /// <summary>True with root motion on: the job blends <see cref="RootVelocityX"/>… over the controller's.</summary>
        public bool RootMotion;

        /// <summary>
        /// True while a hand-off (<see cref="TransitionCharacter.RequestState"/>, or a controller transition <see cref="AnimatorTransitions"/>
        /// replaces) waits for its target: the engine samples <see cref="Sample"/>'s pose off-scene (the controller's state at that time,
        /// with the character's parameters) and hands it to the next <see cref="TransitionCharacter.Frame"/> as the sampled target.
        /// </summary>
        public bool SampleState;

        /// <summary>The state whose pose to sample, when <see cref="SampleState"/>.</summary>
        public StateTarget Sample;

        /// <summary>
        /// True in the frame a <see cref="TransitionCharacter.RequestState"/> hand-off arrives: the weight is already 0 and the engine puts
        /// the controller in <see cref="Play"/> now (Unity: <c>Animator.PlayInFixedTime(hash, layer, seconds)</c>), so this frame and the
        /// next show the state playing on from the in-between's last pose.
        /// </summary>
        public bool PlayState;

        /// <summary>The state to play and its time at this frame, when <see cref="PlayState"/>.</summary>
        public StateTarget Play;
    }
}
