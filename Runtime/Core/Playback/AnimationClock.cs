namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Which clock a character's animation runs on; the values mirror Unity's <c>AnimatorUpdateMode</c>
    /// (Normal, Fixed — formerly AnimatePhysics — and UnscaledTime), so the component converts by cast.
    /// </summary>
    public enum AnimationClockMode
    {
        /// <summary>Rendered frames, scaled game time (Unity: <c>Time.deltaTime</c>); <c>timeScale = 0</c> freezes it.</summary>
        Scaled = 0,

        /// <summary>Physics steps (Unity: <c>FixedUpdate</c>, <c>Time.fixedDeltaTime</c>); no step runs while <c>timeScale = 0</c>.</summary>
        Fixed = 1,

        /// <summary>Rendered frames, real time (Unity: <c>Time.unscaledDeltaTime</c>): keeps playing while the game is paused.</summary>
        Unscaled = 2,
    }

    /// <summary>The engine callback a frame's work comes from.</summary>
    public enum FrameCallback
    {
        /// <summary>Once per rendered frame (Unity: <c>Update</c>).</summary>
        Update,

        /// <summary>Once per physics step, zero or more times per rendered frame (Unity: <c>FixedUpdate</c>).</summary>
        FixedUpdate,
    }

    /// <summary>
    /// The time a transition plays in: it advances by the step of the clock the character's animation runs
    /// on, so a transition keeps pace with the animation it blends over (it freezes with a paused Normal-mode
    /// character, keeps playing with an UnscaledTime one, and steps with physics for a Fixed one). The engine
    /// only reads its own values (delta times) and passes them in; the choice is made here.
    /// </summary>
    public sealed class AnimationClock
    {
        /// <summary>The clock the animation runs on (may change at any frame, as Unity's Animator.updateMode may).</summary>
        public AnimationClockMode Mode { get; set; }

        /// <summary>Seconds this clock has advanced since it was created: the time to give <see cref="TransitionPlayer"/>.</summary>
        public double Time { get; private set; }

        /// <summary>The last step taken by <see cref="Advance"/>.</summary>
        public double LastStep { get; private set; }

        /// <summary>True when <paramref name="callback"/> is where an animation on <paramref name="mode"/> advances (Fixed: physics steps; the others: rendered frames).</summary>
        public static bool Drives(AnimationClockMode mode, FrameCallback callback) =>
            mode == AnimationClockMode.Fixed ? callback == FrameCallback.FixedUpdate : callback == FrameCallback.Update;

        /// <summary>
        /// The seconds an animation on <paramref name="mode"/> advances by in one of its callbacks: the scaled
        /// frame time, the physics step, or the real frame time. Negative or non-finite values count as 0.
        /// </summary>
        public static double Step(AnimationClockMode mode, double deltaTime, double unscaledDeltaTime, double fixedDeltaTime)
        {
            double step;
            switch (mode)
            {
                case AnimationClockMode.Fixed: step = fixedDeltaTime; break;
                case AnimationClockMode.Unscaled: step = unscaledDeltaTime; break;
                default: step = deltaTime; break;
            }

            return step > 0 && !double.IsInfinity(step) ? step : 0;
        }

        /// <summary>
        /// Called from every engine callback with the engine's delta times; advances <see cref="Time"/> when
        /// this callback drives the <see cref="Mode"/>.
        /// </summary>
        /// <returns>True when the callback drives the clock (the caller does its frame's work then); false otherwise.</returns>
        public bool Advance(FrameCallback callback, double deltaTime, double unscaledDeltaTime, double fixedDeltaTime)
        {
            if (!Drives(Mode, callback)) return false;
            LastStep = Step(Mode, deltaTime, unscaledDeltaTime, fixedDeltaTime);
            Time += LastStep;
            return true;
        }
    }
}
