using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// Where a <see cref="TransitionPlayer"/>'s network work runs: <see cref="InferenceWorker"/> (a
    /// background thread; the main thread never waits) or <see cref="MainThreadDecoder"/> (on the main
    /// thread, a bounded amount of work per rendered frame, for engines that must run there). One decoder
    /// serves any number of players of the same model and runs all of their pending work in batches
    /// (one run per graph and number of past keys per round).
    /// </summary>
    public abstract class TransitionDecoder : IDisposable
    {
        private readonly KeyFeatureBuilder _features;

        internal TransitionDecoder(Inbetweener inbetweener)
        {
            Inbetweener = inbetweener ?? throw new ArgumentNullException(nameof(inbetweener));
            FrameRate = inbetweener.Contract.FramesPerSecond;
            _features = new KeyFeatureBuilder(inbetweener.Contract);
        }

        /// <summary>The model's contract (skeleton, trained ranges).</summary>
        public ModelContract Contract => Inbetweener.Contract;

        /// <summary>The model's frame rate (the contract's training fps).</summary>
        public double FrameRate { get; }

        internal Inbetweener Inbetweener { get; }

        /// <summary>Releases the decoder and the <see cref="Inference.Inbetweener"/> it was given.</summary>
        public abstract void Dispose();

        /// <summary>
        /// Main thread, at the request: localizes the keys, builds their features and writes the SLERP
        /// pose of every missing frame (what a frame shows until its network output arrives). Cheap: no
        /// network run.
        /// </summary>
        internal void Prepare(TransitionJob job)
        {
            Transition t = job.Transition;
            Inbetweener inb = Inbetweener;
            job.Localization = inb.LocalizeAndBuild(t, job.LocalRoot, job.LocalRotations, job.Pairs, job.KeyFeatures, _features);
            for (int k = 0; k < t.MissingFrames; k++)
            {
                inb.Baseline(t, job.Localization, job.LocalRoot, job.Pairs, k, job.SlerpRoots, job.SlerpRotations);
            }
        }

        /// <summary>Starts decoding a prepared job (main thread).</summary>
        internal abstract void Start(TransitionJob job);

        /// <summary>
        /// Each rendered frame (main thread): playback needs <paramref name="frames"/> decoded frames of
        /// <paramref name="job"/> by frame time <paramref name="time"/>. Never waits for the network.
        /// </summary>
        internal abstract void Need(TransitionJob job, int frames, double time);

        /// <summary>Blocks until <paramref name="job"/> is decoded or <paramref name="millisecondsTimeout"/> passes (cut-scenes, tests).</summary>
        internal abstract bool Drain(TransitionJob job, int millisecondsTimeout);
    }
}
