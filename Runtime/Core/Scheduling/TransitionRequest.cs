using System;
using System.Threading;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// One request's network work: its keys and missing frames (a <see cref="Transition"/>), the SLERP
    /// pose of every missing frame (written on the main thread at the request, shown until the network's
    /// frame arrives), the localized keys and their features, and how many frames are decoded so far. The
    /// main thread writes the keys before handing the request to a <see cref="TransitionScheduler"/> and reads
    /// frames below <see cref="Decoded"/>; a worker thread writes frame k before publishing Decoded = k + 1
    /// (release/acquire through <see cref="Volatile"/>).
    /// </summary>
    internal sealed class TransitionRequest
    {
        private int _decoded;
        private int _finished = 1;
        private int _cancelled;
        private int _needed;

        public TransitionRequest(Transition transition, ModelContract contract)
        {
            Transition = transition;
            int n = transition.MissingFrames;
            int j = transition.Skeleton.JointCount;
            SlerpRoots = new double[n * 3];
            SlerpRotations = new double[n * j * 4];
            Keys = new LocalizedKeys(contract, transition.PastFrames);
            KeyFeatures = new float[transition.KeyFrameCount * contract.KeyFeatureSize];
        }

        public Transition Transition { get; }

        /// <summary>The SLERP pose of each missing frame (world, n × 3 and n × J × 4): the baseline of the same request.</summary>
        public double[] SlerpRoots { get; }

        /// <summary>See <see cref="SlerpRoots"/>.</summary>
        public double[] SlerpRotations { get; }

        /// <summary>The keys, localized: what every missing frame is decoded against.</summary>
        public LocalizedKeys Keys { get; }

        /// <summary>The request's <c>key_features</c> row (K × 9J), built on the main thread at the request.</summary>
        public float[] KeyFeatures { get; }

        /// <summary>The request's key encoding (R × 2 × K × D), written by the scheduler's keys run; null until the first one.</summary>
        public float[]? KeyMemory { get; set; }

        /// <summary>Order of the request among all of its scheduler's (older first).</summary>
        public long Sequence { get; set; }

        /// <summary>Bumped at every <see cref="Reset"/>: tells a batch row filled for an earlier request of this request from this one.</summary>
        public int Generation { get; private set; }

        /// <summary>Scheduler state (one thread): keys encoded.</summary>
        public bool Encoded { get; set; }

        /// <summary>Scheduler state (one thread): part of a run not collected yet.</summary>
        public bool InFlight { get; set; }

        /// <summary>
        /// Scheduler state (one thread): the row of its group's frame tensor its key memory was last gathered into (−1:
        /// none yet); the row still holds it while the tensor's owner of that row is this request at this <see cref="Generation"/>.
        /// </summary>
        public int FrameRow { get; set; } = -1;

        /// <summary>Missing frames decoded so far (0..n), in order.</summary>
        public int Decoded => Volatile.Read(ref _decoded);

        /// <summary>Missing frames playback needs by now (written by the main thread each frame; the scheduler decodes the most urgent first).</summary>
        public int Needed
        {
            get => Volatile.Read(ref _needed);
            set => Volatile.Write(ref _needed, value);
        }

        /// <summary>True when no scheduler touches the request any more (it may be reused).</summary>
        public bool Finished => Volatile.Read(ref _finished) != 0;

        /// <summary>True when the player no longer wants the frames.</summary>
        public bool Cancelled => Volatile.Read(ref _cancelled) != 0;

        /// <summary>Set when the scheduler failed; the player reports it on the main thread.</summary>
        public Exception? Error { get; set; }

        public void Reset()
        {
            Error = null;
            Encoded = false;
            InFlight = false;
            Generation++;
            Volatile.Write(ref _needed, 0);
            Volatile.Write(ref _decoded, 0);
            Volatile.Write(ref _cancelled, 0);
            Volatile.Write(ref _finished, 0);
        }

        public void Publish(int decoded) => Volatile.Write(ref _decoded, decoded);

        /// <summary>
        /// The model's predicted contacts (4 probabilities, <see cref="Transition.ContactThreshold"/>) of the transition's
        /// frame <paramref name="frame"/> (0 the last past key, 1..n the missing frames, n + 1 the target), once it is
        /// decoded; empty for keys, frames not decoded yet and models without contacts (the locker labels them then).
        /// </summary>
        public ReadOnlySpan<float> ContactsOf(int frame)
        {
            int k = frame - 1;
            if (!Transition.HasFootContacts || k < 0 || k >= Transition.MissingFrames || Decoded <= k) return default;
            return new ReadOnlySpan<float>(Transition.FootContacts, Transition.ContactChannels * k, Transition.ContactChannels);
        }

        public void Finish() => Volatile.Write(ref _finished, 1);

        public void Cancel() => Volatile.Write(ref _cancelled, 1);
    }
}
