namespace DeltaInterpolator.Core.Playback
{
    /// <summary>How a requested transition ended; <see cref="TransitionPlayer.TransitionCompleted"/> reports each request exactly once.</summary>
    public readonly struct TransitionCompletion
    {
        /// <summary>Creates the report.</summary>
        public TransitionCompletion(int requestId, bool reachedTarget, double time)
        {
            RequestId = requestId;
            ReachedTarget = reachedTarget;
            Time = time;
        }

        /// <summary>The id <see cref="TransitionPlayer.RequestTransition"/> returned.</summary>
        public int RequestId { get; }

        /// <summary>True when the target pose was shown; false when a newer request or <see cref="TransitionPlayer.Cancel"/> ended it first.</summary>
        public bool ReachedTarget { get; }

        /// <summary>The frame time at which it ended (seconds).</summary>
        public double Time { get; }
    }
}
