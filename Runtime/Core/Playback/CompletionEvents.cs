using System;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// The completions a <see cref="TransitionPlayer"/> owes its listeners, held until its state is consistent and then fired in
    /// the order a listener expects: the interrupted request, a dropped deferred one, then the one that reached its target.
    /// </summary>
    /// <remarks>Its own type so the player's file stays about playing; value fields only, so queuing allocates nothing.</remarks>
    internal struct CompletionEvents
    {
        private TransitionCompletion? _interruption;
        private TransitionCompletion? _dropped;
        private TransitionCompletion? _completion;

        public void Interrupted(int requestId, double time) => _interruption = new TransitionCompletion(requestId, false, time);

        public void Dropped(int requestId, double time) => _dropped = new TransitionCompletion(requestId, false, time);

        public void Reached(int requestId, double time) => _completion = new TransitionCompletion(requestId, true, time);

        // Events fire after the state is consistent, so a handler may request the next transition (from BeginFrame: without
        // disturbing the pose this frame shows).
        public void Flush(Action<TransitionCompletion>? handler)
        {
            if (_interruption is TransitionCompletion interrupted)
            {
                _interruption = null;
                handler?.Invoke(interrupted);
            }

            if (_dropped is TransitionCompletion dropped)
            {
                _dropped = null;
                handler?.Invoke(dropped);
            }

            if (_completion is TransitionCompletion completed)
            {
                _completion = null;
                handler?.Invoke(completed);
            }
        }
    }
}
