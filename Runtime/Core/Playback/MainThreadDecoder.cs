using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Decodes on the calling (main) thread, lazily: a request runs the keys graph once, and each frame
    /// decodes only the model frames playback has reached (at most one or two per rendered frame at game
    /// frame rates). For engines whose workers must stay on the main thread (Unity Sentis). Without the
    /// lazy graphs a request decodes the whole transition at once.
    /// </summary>
    public sealed class MainThreadDecoder : TransitionDecoder
    {
        /// <summary>Creates the decoder; it owns <paramref name="inbetweener"/>.</summary>
        public MainThreadDecoder(Inbetweener inbetweener)
            : base(inbetweener)
        {
        }

        /// <inheritdoc />
        public override void Dispose() => Inbetweener.Dispose();

        internal override void Start(TransitionJob job)
        {
            job.Reset();
            var t = job.Transition;
            if (!Inbetweener.SupportsLazyDecoding)
            {
                Inbetweener.Inbetween(t);
                job.Publish(t.MissingFrames);
                job.Finish();
                return;
            }

            // Each job keeps its own lazy decoder (jobs are pooled per player and shape), so players sharing
            // this decoder never overwrite each other's key encoding.
            job.Lazy ??= Inbetweener.CreateLazy(t.PastFrames, t.MissingFrames);
            job.Lazy.Begin(t);
            job.Finish();
        }

        internal override void Ensure(TransitionJob job, int frames)
        {
            LazyDecoder? lazy = job.Lazy;
            if (lazy == null) return;
            for (int k = job.Decoded; k < frames; k++)
            {
                lazy.DecodeFrame(k);
                job.Publish(k + 1);
            }
        }
    }
}
