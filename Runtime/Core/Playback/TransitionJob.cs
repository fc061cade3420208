using System;
using System.Threading;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// One request's network work: its keys and missing frames (a <see cref="Transition"/>) and how many
    /// frames are decoded so far. The main thread writes the keys before handing the job to a
    /// <see cref="TransitionDecoder"/> and reads frames below <see cref="Decoded"/>; a worker thread writes
    /// frame k before publishing Decoded = k + 1 (release/acquire through <see cref="Volatile"/>).
    /// </summary>
    internal sealed class TransitionJob
    {
        private int _decoded;
        private int _finished = 1;
        private int _cancelled;

        public TransitionJob(Transition transition)
        {
            Transition = transition;
        }

        public Transition Transition { get; }

        /// <summary>Missing frames decoded so far (0..n), in order.</summary>
        public int Decoded => Volatile.Read(ref _decoded);

        /// <summary>True when no decoder touches the job any more (it may be reused).</summary>
        public bool Finished => Volatile.Read(ref _finished) != 0;

        /// <summary>True when the player no longer wants the frames.</summary>
        public bool Cancelled => Volatile.Read(ref _cancelled) != 0;

        /// <summary>Set when the decoder failed; the player reports it on the main thread.</summary>
        public Exception? Error { get; set; }

        /// <summary>The main-thread decoder's lazy decoder for this job's shape (its own, not shared).</summary>
        public LazyDecoder? Lazy { get; set; }

        public void Reset()
        {
            Error = null;
            Volatile.Write(ref _decoded, 0);
            Volatile.Write(ref _cancelled, 0);
            Volatile.Write(ref _finished, 0);
        }

        public void Publish(int decoded) => Volatile.Write(ref _decoded, decoded);

        public void Finish() => Volatile.Write(ref _finished, 1);

        public void Cancel() => Volatile.Write(ref _cancelled, 1);
    }
}
