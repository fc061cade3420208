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
