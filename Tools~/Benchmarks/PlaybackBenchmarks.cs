using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using System.IO;
using BenchmarkDotNet.Attributes;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.OnnxRuntime;

namespace DeltaInterpolator.Benchmarks
{
    /// <summary>
    /// The main-thread cost of the Unity component per rendered frame, for 1, 16 and 64 characters of 22
    /// bones (the shipped LaFAN1 model on ONNX Runtime, one shared <see cref="WorkerThreadScheduler"/>): every
    /// character mid-transition, so each frame interpolates between decoded model frames, converts to
    /// the character's space, blends over the animation stream with a weight between 0 and 1 (the
    /// costliest case: two slerps per bone) and records the pose shown. Divide by Characters for the
    /// per-character cost; it must allocate 0 B.
    /// <code>dotnet run -c Release --project Tools~/Benchmarks -- --filter '*PlaybackBenchmarks*'</code>
    /// </summary>
    [MemoryDiagnoser]
    public class PlaybackBenchmarks
    {
        private const double FrameTime = 1.0 / 144;
        private const double Duration = 1.0;
        private readonly List<TransitionPlayer> _players = new List<TransitionPlayer>();
        private WorkerThreadScheduler _worker = null!;
        private Stream[] _streams = null!;
        private double _start;
        private int _frame;

        /// <summary>Characters playing a transition at once.</summary>
        [Params(1, 16, 64)]
        public int Characters { get; set; }

        [GlobalSetup]
        public void Setup()
        {
            _worker = new WorkerThreadScheduler(OnnxRuntimeInbetweener.Load(PlaybackSetup.ShippedModel, requireLazy: true));
            _streams = new Stream[Characters];
            for (int c = 0; c < Characters; c++)
            {
                // Blend-in over the whole transition: the weight stays strictly between 0 and 1.
                var settings = new PlaybackSettings { BlendInSeconds = Duration, BlendOutSeconds = 0.2 };
                TransitionPlayer player = PlaybackSetup.Player(_worker, settings, c, out _streams[c]);
                _start = player.History.NewestTime;
                player.RequestTransition(_streams[c].Root, _streams[c].Rotations, Duration);
                if (!player.WaitUntilDecoded(60000)) throw new InvalidOperationException("decoding timed out");
                _players.Add(player);
            }
        }

        [GlobalCleanup]
        public void Cleanup() => _worker.Dispose();

        /// <summary>One rendered frame of every character: BeginFrame + PoseBlend + Record (TransitionPlayer.Step).</summary>
        [Benchmark]
        public void Frame()
        {
            // Frame times cycle through the first 0.9 s of the transition (time restarting clears the
            // history, which costs nothing extra): every frame interpolates decoded frames and blends.
            _frame = (_frame + 1) % 129;
            double time = _start + (_frame + 1) * FrameTime;
            for (int c = 0; c < _players.Count; c++) _players[c].Step(time, ref _streams[c]);
        }
    }

    /// <summary>
    /// The main-thread cost of <see cref="TransitionPlayer.RequestTransition"/> for a 22-bone character: the
    /// history resampled to 30 fps, converted to the model's space, handed to the decoder. With the
    /// <see cref="WorkerThreadScheduler"/> the network runs on its thread; with the <see cref="MainThreadScheduler"/>
    /// the request also runs the keys graph on the calling thread (for comparison).
    /// </summary>
    [MemoryDiagnoser]
    public class RequestBenchmarks
    {
        private TransitionScheduler _decoder = null!;
        private TransitionPlayer _player = null!;
        private Stream _stream;

        /// <summary>Where the network runs.</summary>
        [Params("worker", "main")]
        public string Decoder { get; set; } = "worker";

        [GlobalSetup]
        public void Setup()
        {
            Inbetweener model = OnnxRuntimeInbetweener.Load(PlaybackSetup.ShippedModel, requireLazy: true);
            _decoder = Decoder == "worker" ? new WorkerThreadScheduler(model) : new MainThreadScheduler(model);
            _player = PlaybackSetup.Player(_decoder, new PlaybackSettings(), 0, out _stream);
        }

        [GlobalCleanup]
        public void Cleanup() => _decoder.Dispose();

        /// <summary>One request of 0.5 s (15 model frames) from the newest recorded pose.</summary>
        [Benchmark]
        public int Request() => _player.RequestTransition(_stream.Root, _stream.Rotations, 0.5);

        /// <summary>
        /// A request and the wait until all 14 missing frames are decoded: how long after a request the
        /// whole transition is ready (worker: off the main thread; main: all of it on the main thread).
        /// </summary>
        [Benchmark]
        public bool RequestUntilDecoded()
        {
            _player.RequestTransition(_stream.Root, _stream.Rotations, 0.5);
            return _player.WaitUntilDecoded(60000);
        }
    }

    /// <summary>An animation stream on arrays (the Unity glue's is on transform stream handles).</summary>
    public struct Stream : IPoseStream
    {
        public double[] Root;
        public double[] Rotations;

        public int BoneCount => Rotations.Length / 4;

        public Vector3D ReadRootPosition() => Vector3D.Read(Root, 0);

        public void WriteRootPosition(Vector3D position) => position.Write(Root, 0);

        public QuaternionD ReadLocalRotation(int bone) => QuaternionD.Read(Rotations, 4 * bone);

        public void WriteLocalRotation(int bone, QuaternionD rotation) => rotation.Write(Rotations, 4 * bone);
    }

    internal static class PlaybackSetup
    {
        /// <summary>
        /// The shipped default model (<see cref="ShippedModels.Default"/>, found as the CLI finds it). Not the LaFAN1
        /// model: its graphs are contract version 1 (one row per run), so a "batched" crowd on it ran one character per
        /// run and the crowd benchmark's batched case measured no batching at all.
        /// </summary>
        public static string ShippedModel
        {
            get
            {
                string path = ShippedModels.Find(ShippedModels.Default);
                if (!File.Exists(path)) throw new FileNotFoundException($"{ShippedModels.Default} not found above {Directory.GetCurrentDirectory()} or {AppContext.BaseDirectory}");
                return path;
            }
        }

        /// <summary>A player for a character with the model's bones, its history filled with 1 s of motion at 144 fps.</summary>
        public static TransitionPlayer Player(TransitionScheduler decoder, PlaybackSettings settings, int seed, out Stream stream)
        {
            ModelContract contract = decoder.Contract;
            var map = new NamePoseConverter(contract.Skeleton, contract.UnitScale, contract.Skeleton.Names);
            var player = new TransitionPlayer(map, decoder, settings);
            int bones = map.BoneCount;
            stream = new Stream { Root = new double[3], Rotations = new double[4 * bones] };
            var random = new Random(seed);
            var axes = new Vector3D[bones];
            for (int b = 0; b < bones; b++) axes[b] = new Vector3D(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            for (int f = 0; f <= 144; f++)
            {
                double t = f / 144.0;
                new Vector3D(0, 0.9, 1.2 * t).Write(stream.Root, 0);
                for (int b = 0; b < bones; b++)
                {
                    Quaternions.FromAxisAngle((1 / axes[b].Length) * axes[b], 0.5 * Math.Sin(3 * t + b)).Write(stream.Rotations, 4 * b);
                }

                player.Step(t, ref stream);
            }

            return player;
        }
    }
}
