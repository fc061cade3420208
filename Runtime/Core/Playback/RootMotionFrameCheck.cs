using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>The frame a root velocity on the animation stream is given in.</summary>
    public enum RootVelocityFrame
    {
        /// <summary>The character's own frame (Unity: the Animator's transform rotation turns it into the world).</summary>
        Local = 0,

        /// <summary>The world's frame, as <c>Animator.velocity</c> reports it.</summary>
        World = 1,
    }

    /// <summary>
    /// Decides, while the game runs, which frame the engine's stream velocity is in (Unity:
    /// <c>AnimationStream.velocity</c>, a frame its C# source does not name) by comparing it with the velocity the engine
    /// then applied in the world (Unity: <c>Animator.velocity</c>) and the character's rotation, in frames where no
    /// transition changed the stream. It starts from <see cref="RootVelocityFrame.Local"/>, the frame Unity's own
    /// Kinematica writes (<c>Documentation~/unity-verification.md</c>), and settles on the frame that matched in
    /// <see cref="FramesOfEvidence"/> frames in a row that tell the two apart; when neither matches that many times in a
    /// row it says so once (<see cref="Observe"/> returns the message).
    /// </summary>
    /// <remarks>
    /// Directions decide the frame: how an engine scales root motion with the character does not change its frame. The
    /// scale itself (<see cref="Scale"/>: applied speed ÷ stream speed, e.g. a scaled character's) is measured in the
    /// first <see cref="FramesOfEvidence"/> frames whose direction matches the frame in use, facing any way. Frames where
    /// the character moves slower than <see cref="MinimumSpeed"/>, or faces so close to the world's axes that both frames
    /// give the same direction within <see cref="ToleranceDegrees"/>, are no evidence for the frame. Allocation-free
    /// except for the one message; main thread only.
    /// </remarks>
    public sealed class RootMotionFrameCheck
    {
        /// <summary>Largest angle (degrees) between the predicted and the applied world velocity that still matches.</summary>
        public const double ToleranceDegrees = 10.0;

        /// <summary>Speed (m/s, in the stream and in the world) below which a frame's direction is noise.</summary>
        public const double MinimumSpeed = 0.05;

        /// <summary>Frames in a row that must agree before the check decides, or says that neither frame matches.</summary>
        public const int FramesOfEvidence = 5;

        private static readonly double CosTolerance = Math.Cos(ToleranceDegrees * Math.PI / 180.0);

        private RootVelocityFrame _candidate;
        private int _agreeing;
        private int _neither;
        private bool _told;
        private double _ratios;
        private int _ratioCount;

        /// <summary>The frame used until the evidence decides (<see cref="Frame"/>).</summary>
        public RootMotionFrameCheck(RootVelocityFrame assumed = RootVelocityFrame.Local)
        {
            Frame = assumed;
        }

        /// <summary>The frame the stream's velocity is taken to be in: the decided one, or the assumed one until then.</summary>
        public RootVelocityFrame Frame { get; private set; }

        /// <summary>True once <see cref="FramesOfEvidence"/> frames in a row matched <see cref="Frame"/> and not the other, or after <see cref="Assume"/>.</summary>
        public bool Decided { get; private set; }

        /// <summary>How much faster the engine moves the character than the stream's velocity says (1 until measured).</summary>
        public double Scale { get; private set; } = 1.0;

        /// <summary>True once <see cref="FramesOfEvidence"/> frames in a row matched neither frame (said once by <see cref="Observe"/>).</summary>
        public bool NeitherMatched => _told;

        /// <summary>
        /// One frame's evidence, from a frame in which nothing changed the stream's velocity between the stream and the
        /// engine (no transition played).
        /// </summary>
        /// <param name="streamVelocity">The velocity on the stream (the controller's root motion, per second).</param>
        /// <param name="appliedVelocity">The velocity the engine applied to the character (world, per second).</param>
        /// <param name="rotation">The character's rotation in the world when the engine evaluated that frame.</param>
        /// <returns>A one-line message the first time neither frame matched for <see cref="FramesOfEvidence"/> frames in a row; otherwise null.</returns>
        public string? Observe(Vector3D streamVelocity, Vector3D appliedVelocity, QuaternionD rotation)
        {
            double streamSpeed = streamVelocity.Length, appliedSpeed = appliedVelocity.Length;
            if (!(streamSpeed >= MinimumSpeed) || !(appliedSpeed >= MinimumSpeed) || double.IsInfinity(streamSpeed) || double.IsInfinity(appliedSpeed)) return null;
            Vector3D local = Quaternions.Apply(rotation, streamVelocity);
            double cosLocal = Vector3D.Dot(local, appliedVelocity) / (local.Length * appliedSpeed);
            double cosWorld = Vector3D.Dot(streamVelocity, appliedVelocity) / (streamSpeed * appliedSpeed);
            bool localMatches = cosLocal >= CosTolerance, worldMatches = cosWorld >= CosTolerance;
            if (_ratioCount < FramesOfEvidence && (Frame == RootVelocityFrame.Local ? localMatches : worldMatches))
            {
                _ratios += appliedSpeed / streamSpeed;
                if (++_ratioCount == FramesOfEvidence) Scale = _ratios / FramesOfEvidence;
            }

            if (localMatches && worldMatches) return null;   // facing along the world's axes: both frames agree
            if (!localMatches && !worldMatches)
            {
                _agreeing = 0;
                if (++_neither < FramesOfEvidence || _told) return null;
                _told = true;
                return FormattableString.Invariant(
                    $"root motion: the Animator applied a velocity {Degrees(Math.Max(cosLocal, cosWorld)):F0}° away from both the character's frame and the world's frame of the stream's velocity in {FramesOfEvidence} frames in a row (a script or another playable changes root motion after the Animator Controller?); transitions keep the {Frame} frame and may push the character sideways");
            }

            _neither = 0;
            RootVelocityFrame matched = localMatches ? RootVelocityFrame.Local : RootVelocityFrame.World;
            if (matched != _candidate) _agreeing = 0;
            _candidate = matched;
            if (++_agreeing >= FramesOfEvidence && !Decided)
            {
                // A frame other than the one assumed: its scale is measured again, in its own frames.
                if (matched != Frame) { _ratios = 0; _ratioCount = 0; Scale = 1.0; }
                Frame = matched;
                Decided = true;
            }

            return null;
        }

        /// <summary>Takes <paramref name="frame"/> as decided (an engine whose frame is known), whatever the evidence says later.</summary>
        public void Assume(RootVelocityFrame frame)
        {
            Frame = frame;
            Decided = true;
        }

        /// <summary>A velocity on the stream (in <see cref="Frame"/>) in the world, for a character at <paramref name="rotation"/>.</summary>
        public Vector3D ToWorld(Vector3D streamVelocity, QuaternionD rotation) =>
            Scale * (Frame == RootVelocityFrame.Local ? Quaternions.Apply(rotation, streamVelocity) : streamVelocity);

        /// <summary>A world velocity as the stream takes it (in <see cref="Frame"/>), for a character at <paramref name="rotation"/>.</summary>
        public Vector3D ToStream(Vector3D worldVelocity, QuaternionD rotation) =>
            (1.0 / Scale) * (Frame == RootVelocityFrame.Local ? Quaternions.Apply(Quaternions.Inverse(rotation), worldVelocity) : worldVelocity);

        private static double Degrees(double cos) => Math.Acos(Math.Max(-1.0, Math.Min(1.0, cos))) * 180.0 / Math.PI;
    }
}
