using System;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>Where a character's transitions stand: waiting for what they need, running, or failed.</summary>
    public enum PlaybackState
    {
        /// <summary>Not started: something it needs (settings, a model) is not there yet; no error.</summary>
        Waiting,

        /// <summary>Built and playing frames.</summary>
        Running,

        /// <summary>Stopped by an error (the model, the rig, the inference engine); <see cref="PlaybackStatus.Reason"/> says which and what to do.</summary>
        Failed,
    }

    /// <summary>
    /// The front end's state machine around a <see cref="TransitionPlayer"/>: it plays frames only while
    /// <see cref="PlaybackState.Running"/>, and a failure of the inference engine during a frame (any exception
    /// from a run: <see cref="InferenceFailedException"/>) moves it to <see cref="PlaybackState.Failed"/> once,
    /// with one message naming the model, the engine and what to do, so a character never stays silently idle.
    /// The Unity component logs <see cref="Reason"/> and disables itself on that transition.
    /// </summary>
    public sealed class PlaybackStatus
    {
        /// <summary>The current state.</summary>
        public PlaybackState State { get; private set; } = PlaybackState.Waiting;

        /// <summary>Why the state is not <see cref="PlaybackState.Running"/> (what is missing, or what failed and what to do); empty while running.</summary>
        public string Reason { get; private set; } = "not started";

        /// <summary>The exception behind <see cref="PlaybackState.Failed"/>, if any.</summary>
        public Exception? Error { get; private set; }

        /// <summary>True while <see cref="PlaybackState.Running"/>.</summary>
        public bool IsRunning => State == PlaybackState.Running;

        /// <summary>Waits for <paramref name="reason"/> (e.g. no settings assigned yet); not an error.</summary>
        public void Wait(string reason) => Set(PlaybackState.Waiting, reason, null);

        /// <summary>Built: frames play from now on (also after a failure, once the front end rebuilt what failed).</summary>
        public void Run() => Set(PlaybackState.Running, "", null);

        /// <summary>Stops with <paramref name="reason"/> (what was wrong and what to do).</summary>
        public void Fail(string reason, Exception? error = null) => Set(PlaybackState.Failed, reason, error);

        /// <summary>
        /// Whether a frame should try <see cref="TryStart"/>: only while <see cref="PlaybackState.Waiting"/> with what the start
        /// needs there (<paramref name="ready"/>, e.g. a settings asset). Never after a failure: a model that failed to load is not
        /// loaded again every frame; the front end calls <see cref="Wait"/> (e.g. when the component is enabled again) to retry.
        /// </summary>
        public bool ShouldStart(bool ready) => ready && State == PlaybackState.Waiting;

        /// <summary>
        /// Starts the character with <paramref name="start"/> (load the model, bind the rig): <see cref="PlaybackState.Running"/> when it
        /// returns, <see cref="PlaybackState.Failed"/> with one reason when it throws anything, whatever the type (an engine's own
        /// assertion, a backend factory's exception, a refusal of the rig), so a failed start is never retried by the next frame.
        /// Fatal exceptions (<see cref="IsFatal"/>) fail it too, then propagate.
        /// </summary>
        /// <returns>True when started; false when it failed now (<see cref="Reason"/> says why and what to do).</returns>
        public bool TryStart(Action start, string model)
        {
            if (start == null) throw new ArgumentNullException(nameof(start));
            try
            {
                start();
                Run();
                return true;
            }
            catch (Exception e)
            {
                Fail(StartFailure(model, e), e);
                if (IsFatal(e)) throw;
                return false;
            }
        }

        /// <summary>Exceptions after which the process should not go on as if nothing happened: they are reported, then rethrown.</summary>
        public static bool IsFatal(Exception error) => error is OutOfMemoryException || error is StackOverflowException || error is System.Threading.ThreadAbortException;

        /// <summary>
        /// The message for a failed start: the package's own refusals (a model that does not fit its contract, a rig that cannot be
        /// mapped, a missing setting or engine) already say what and what to do; anything else is named with its type and what to do.
        /// </summary>
        public static string StartFailure(string model, Exception error)
        {
            if (error is DataFormatException || error is Retargeting.JointMapException || error is ArgumentException || error is InvalidOperationException) return error.Message;
            return $"the in-betweening model '{model}' could not be loaded ({error.GetType().Name}: {error.Message}); " +
                "check the model asset's inspector for errors, try another inference engine in the settings, then enable the component again";
        }

        /// <summary>
        /// <see cref="TransitionPlayer.BeginFrame"/> while running. When the engine fails in this frame the
        /// state becomes <see cref="PlaybackState.Failed"/> with <see cref="InferenceFailure"/>'s message;
        /// other exceptions (an event handler's) pass through. Allocates nothing unless it fails.
        /// </summary>
        /// <returns>True when the frame played; false when not running or when it failed now (see <see cref="State"/>).</returns>
        public bool TryBeginFrame(TransitionPlayer player, double time, string model, string engine)
        {
            if (player == null) throw new ArgumentNullException(nameof(player));
            if (State != PlaybackState.Running) return false;
            try
            {
                player.BeginFrame(time);
                return true;
            }
            catch (InferenceFailedException e)
            {
                Fail(InferenceFailure(model, engine, e), e);
                return false;
            }
        }

        /// <summary>The message for a failed run: which model on which engine, what the engine said, and what to do.</summary>
        public static string InferenceFailure(string model, string engine, Exception error)
        {
            Exception engineError = error is InferenceFailedException && error.InnerException != null ? error.InnerException : error;
            return $"the in-betweening model '{model}' failed on the inference engine '{engine}' while playing ({engineError.GetType().Name}: {engineError.Message}); " +
                "transitions are stopped. Check the model asset's inspector for errors, try another inference engine (or a CPU backend) in the settings, then enable the component again";
        }

        private void Set(PlaybackState state, string reason, Exception? error)
        {
            State = state;
            Reason = reason ?? "";
            Error = error;
        }
    }
}
