using DeltaInterpolator.Core.Scheduling;
using BenchmarkDotNet.Attributes;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Evaluation.Speed;
using DeltaInterpolator.OnnxRuntime;

namespace DeltaInterpolator.Benchmarks
{
    /// <summary>
    /// The crowd of <c>inbetween speed --characters N</c> through BenchmarkDotNet (issue 19, item 4): N characters
    /// (1, 16, 64, 256) all request a transition (24–36 model frames, a quarter with 4 past keys) in the same
    /// rendered frame at 60 fps, then play; one invocation is one rendered frame — every player's frame, and the
    /// network runs it needs, decoded on the main thread with no per-frame budget, one model frame per character
    /// per run — batched (every character's work in one run per graph and shape) or one run per character.
    /// Each iteration re-requests (not timed) and times the 60 frames after, the transitions' whole length.
    /// Compare Batched=True with Batched=False at the same Characters for the speed-up; it must allocate 0 B.
    /// <code>dotnet run -c Release --project Tools~/Benchmarks -- --filter '*CrowdBenchmarks*'</code>
    /// (one core as the issue asks: prefix <c>taskset -c 0</c>).
    /// </summary>
    [MemoryDiagnoser]
    public class CrowdBenchmarks
    {
        private MainThreadScheduler _decoder = null!;
        private Crowd _crowd = null!;

        /// <summary>Characters in the crowd.</summary>
        [Params(1, 16, 64, 256)]
        public int Characters { get; set; }

        /// <summary>One run per graph and shape for all characters (true) or one run per character (false).</summary>
        [Params(true, false)]
        public bool Batched { get; set; }

        [GlobalSetup]
        public void Setup()
        {
            var model = OnnxRuntimeInbetweener.Load(PlaybackSetup.ShippedModel, requireLazy: true);
            _decoder = new MainThreadScheduler(model, Batched ? 256 : 1, framesPerRun: 1) { TokensPerFrame = int.MaxValue };
            _crowd = new Crowd(_decoder, Characters);
            _crowd.Warm();
            // A first round creates the batch tensors and bindings.
            _crowd.RequestAll();
            _crowd.PlayFor(1.3);
        }

        [IterationSetup]
        public void RequestAll() => _crowd.RequestAll();

        /// <summary>One rendered frame of the whole crowd.</summary>
        [Benchmark]
        [InvocationCount(60)]
        public void RenderedFrame() => _crowd.Step();

        [GlobalCleanup]
        public void Cleanup() => _decoder.Dispose();
    }
}
