using System;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Where a <see cref="TransitionPlayer"/>'s network work runs: <see cref="InferenceWorker"/> (a
    /// background thread; the main thread never waits) or <see cref="MainThreadDecoder"/> (lazy decoding
    /// on the calling thread, for engines that must run there). One decoder serves any number of players
    /// of the same model.
    /// </summary>
    public abstract class TransitionDecoder : IDisposable
    {
        internal TransitionDecoder(Inbetweener inbetweener)
        {
            Inbetweener = inbetweener ?? throw new ArgumentNullException(nameof(inbetweener));
            FrameRate = ModelFrameRate.Of(inbetweener.Contract);
        }

        /// <summary>The model's contract (skeleton, trained ranges).</summary>
        public ModelContract Contract => Inbetweener.Contract;

        /// <summary>The model's frame rate (the contract's training fps).</summary>
        public double FrameRate { get; }

        internal Inbetweener Inbetweener { get; }

        /// <summary>Releases the decoder and the <see cref="Inference.Inbetweener"/> it was given.</summary>
        public abstract void Dispose();

        /// <summary>Starts decoding a job whose keys are written (main thread).</summary>
        internal abstract void Start(TransitionJob job);

        /// <summary>Makes sure at least <paramref name="frames"/> frames are decoded, when this decoder decodes on demand (main thread).</summary>
        internal abstract void Ensure(TransitionJob job, int frames);
    }
}
