using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.OnnxRuntime;
using DeltaInterpolator.Tests.Playback;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Many characters on one scheduler in a simulated 60 fps frame loop: batched runs equal one run per
    /// character (real ONNX Runtime, tiny model, contract version 2 and the version 1 file), a frame whose
    /// network output is late shows the request's SLERP pose and the correction eases in without a hold or
    /// a pop (a stand-in backend with a known latency), a burst of requests is spread over frames by the
    /// scheduler's budget (a stand-in backend that counts the work), and a playing crowd allocates nothing.
    /// </summary>
    [TestFixture]
    public sealed class CrowdTests
    {
        private const double Fps = 60;

        [Test]
        public void BatchedRunsEqualOneRunPerCharacterAndOldFilesStillLoad()
        {
            using var batched = new Crowd(new MainThreadScheduler(OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true)), 12, seed: 1);
            using var single = new Crowd(new MainThreadScheduler(OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true), maxBatch: 1), 12, seed: 1);
            using var v1 = new Crowd(new MainThreadScheduler(OnnxRuntimeInbetweener.Load(V1Model, requireLazy: true)), 12, seed: 1);
            Assert.That(v1.Scheduler.Contract.ContractVersion, Is.EqualTo(1));
            foreach (Crowd c in new[] { batched, single, v1 })
            {
                c.PlayUntil(0.5);
                c.RequestAll();
                c.PlayUntil(1.3);
            }

            var b = (MainThreadScheduler)batched.Scheduler;
            var s = (MainThreadScheduler)single.Scheduler;
            Assert.That(b.Batches.Runs, Is.LessThan(s.Batches.Runs / 4), "in far fewer runs");
            for (int i = 0; i < batched.Players.Count; i++)
            {
                TransitionRequest x = batched.Players[i].CurrentRequest!, y = single.Players[i].CurrentRequest!, z = v1.Players[i].CurrentRequest!;
                Assert.That(z.Transition.MissingFrames, Is.EqualTo(x.Transition.MissingFrames), $"character {i}: the same request on the version 1 file");
                Assert.That(z.Transition.PastFrames, Is.EqualTo(x.Transition.PastFrames), $"character {i}: the same request on the version 1 file");
                Assert.That(x.Decoded, Is.EqualTo(x.Transition.MissingFrames));
                Assert.That(y.Decoded, Is.EqualTo(y.Transition.MissingFrames));
                Assert.That(MaxAbs(x.Transition.LocalRotations, y.Transition.LocalRotations), Is.LessThan(1e-5), $"character {i}: batched vs unbatched");
                for (int e = 0; e < x.Transition.RootPositions.Length; e++)
                {
                    Assert.That(Math.Abs(x.Transition.RootPositions[e] - y.Transition.RootPositions[e]), Is.LessThan(1e-5 / 0.01), "root positions (data units, cm; 1e-5 m)");
                }
                Assert.That(MaxAbs(x.Transition.LocalRotations, z.Transition.LocalRotations), Is.LessThan(1e-5), $"character {i}: version 2 vs the version 1 file");
            }
        }

        [Test]
        public void WhenTransitionsEndThePlayingCharactersKeepTheirBatchRows()
        {
            // 12 characters whose transitions end at five different times (0.4–0.8 s): as each ends, the characters
            // still playing keep the frame-batch row that holds their key encoding, so each encoding is copied into the
            // batch once, plus once per character that has to move into a row freed below the shrinking batch.
            using var crowd = new Crowd(new MainThreadScheduler(OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true), framesPerRun: 1), 12, seed: 3);
            var scheduler = (MainThreadScheduler)crowd.Scheduler;
            crowd.PlayUntil(0.5);
            crowd.RequestAll();
            long before = scheduler.Batches.KeyMemoryCopies;
            int moves = 0;
            var rows = new int[12];
            crowd.Step();
            for (int i = 0; i < 12; i++) rows[i] = crowd.Players[i].CurrentRequest!.FrameRow;
            while (crowd.Time < crowd.RequestTime + 1.0)
            {
                crowd.Step();
                for (int i = 0; i < 12; i++)
                {
                    TransitionRequest r = crowd.Players[i].CurrentRequest!;
                    if (r.FrameRow == rows[i]) continue;
                    moves++;
                    rows[i] = r.FrameRow;
                }
            }

            long copies = scheduler.Batches.KeyMemoryCopies - before;
            foreach (TransitionPlayer p in crowd.Players) Assert.That(p.CurrentRequest!.Decoded, Is.EqualTo(p.CurrentRequest.Transition.MissingFrames), "every transition decoded");
            Assert.That(copies, Is.EqualTo(12 + moves), "one copy per request, and one per move");
            // A row frees only when a transition ends, and a character moves only into a freed row: at most one move per
            // transition that ends while others of its group (4 or 10 past keys) still play, 12 − 2. Rows that shift up
            // behind each ended transition moved 15 here.
            Assert.That(moves, Is.LessThanOrEqualTo(12 - 2), "a character moves only into a row freed by an ended transition");
        }

        [TestCase(0, false)]
        [TestCase(2, false)]
        [TestCase(5, false)]
        [TestCase(0, true)]
        [TestCase(2, true)]
        [TestCase(5, true)]
        public void LateFramesShowSlerpAndTheCorrectionEasesInWithoutHoldOrPop(int latencyFrames, bool device)
        {
            using var crowd = new Crowd(new MainThreadScheduler(StandInInbetweener(latencyFrames, out _, device)), 8, seed: 2);
            crowd.PlayUntil(0.5);
            crowd.RequestAll();
            var records = new List<(double U, double[] Shown, double Correction)>[crowd.Players.Count];
            for (int i = 0; i < records.Length; i++) records[i] = new List<(double, double[], double)>();
            while (crowd.Time < crowd.RequestTime + 0.38)
            {
                crowd.Step();
                for (int i = 0; i < crowd.Players.Count; i++)
                {
                    TransitionPlayer p = crowd.Players[i];
                    double u = (crowd.Time - crowd.RequestTime) / (p.TargetTime - crowd.RequestTime) * p.GapFrames;
                    var model = new double[4 * crowd.Map.JointCount];
                    crowd.Map.ToModel(p.PoseRoot, p.PoseRotations, new double[3], model);
                    records[i].Add((u, model, p.Correction));
                }
            }

            double slack = 0.5 * Math.PI / 180;
            bool sawSlerp = false, sawEase = false;
            for (int i = 0; i < crowd.Players.Count; i++)
            {
                TransitionPlayer p = crowd.Players[i];
                Assert.That(p.HeldFrames, Is.EqualTo(0), "never a frozen frame");
                Assert.That(p.WaitUntilDecoded(10000), Is.True);
                TransitionRequest job = p.CurrentRequest!;
                for (int r = 0; r < records[i].Count; r++)
                {
                    var (u, shown, correction) = records[i][r];
                    double[] slerp = At(job, u, model: false);
                    double[] net = At(job, u, model: true);
                    if (correction == 0)
                    {
                        sawSlerp |= latencyFrames > 0;
                        Assert.That(MaxAngle(shown, slerp), Is.LessThan(1e-6), $"character {i}, frame {r}: a late frame shows the request's SLERP pose");
                    }
                    else if (correction == 1)
                    {
                        Assert.That(MaxAngle(shown, net), Is.LessThan(1e-6), $"character {i}, frame {r}: the network's pose");
                    }
                    else
                    {
                        sawEase = true;
                    }

                    if (r == 0) continue;
                    var (u0, shown0, _) = records[i][r - 1];
                    double[] slerp0 = At(job, u0, model: false);
                    double[] net0 = At(job, u0, model: true);
                    for (int j = 0; j < crowd.Map.JointCount; j++)
                    {
                        double turn = EaseIn.Angle(shown0, shown, j);
                        double bound = 1.25 * Math.Max(EaseIn.Angle(slerp0, slerp, j), EaseIn.Angle(net0, net, j)) + slack;
                        Assert.That(turn, Is.LessThanOrEqualTo(bound), $"character {i}, frame {r}, joint {j}: no pop");
                    }
                }

                // It rises as fast as the turn rule allows: at once without latency, over several frames after a late answer.
                double last = records[i][records[i].Count - 1].Correction;
                if (latencyFrames == 0) Assert.That(last, Is.EqualTo(1.0), "no latency: the network's pose from the first frames on");
                else if (latencyFrames <= 2) Assert.That(last, Is.GreaterThan(0.0), "the correction is easing in");
            }

            if (latencyFrames > 0) Assert.That(sawSlerp, Is.True, "some frames were late");
            if (latencyFrames == 2) Assert.That(sawEase, Is.True, "and the correction eased in");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void ABurstOfRequestsIsSpreadOverFramesWithinTheBudget(bool device)
        {
            Inbetweener model = StandInInbetweener(0, out StandInBackend[] graphs, device);
            var scheduler = new MainThreadScheduler(model) { TokensPerFrame = 200 };
            using var crowd = new Crowd(scheduler, 64, seed: 3);
            crowd.PlayUntil(0.5);
            crowd.RequestAll();
            int frames = 0, maxTokens = 0;
            long before = graphs[1].Tokens + graphs[2].Tokens;
            while (crowd.Time < crowd.RequestTime + 0.4)
            {
                crowd.Step();
                long now = graphs[1].Tokens + graphs[2].Tokens;
                maxTokens = Math.Max(maxTokens, (int)(now - before));
                Assert.That(scheduler.LastFrameTokens, Is.EqualTo(now - before), "the stand-in ran what the scheduler says it scheduled");
                before = now;
                frames++;
            }

            Assert.That(maxTokens, Is.LessThanOrEqualTo(200), "no frame schedules more than its budget");
            Assert.That(maxTokens, Is.GreaterThan(150), "and the budget is used");
            foreach (TransitionPlayer p in crowd.Players)
            {
                Assert.That(p.HeldFrames, Is.EqualTo(0));
                Assert.That(p.DecodedFrames, Is.GreaterThan(0), "every character got its network frames within 0.4 s");
            }
        }

        [Test]
        public void SlerpOnlyCharactersNeverRunTheNetwork()
        {
            Inbetweener model = StandInInbetweener(0, out StandInBackend[] graphs);
            using var crowd = new Crowd(new MainThreadScheduler(model), 4, seed: 4, new PlaybackSettings { SlerpOnly = true });
            crowd.PlayUntil(0.5);
            long runs = graphs[1].Runs + graphs[2].Runs;
            crowd.RequestAll();
            crowd.PlayUntil(1.5);
            Assert.That(graphs[1].Runs + graphs[2].Runs, Is.EqualTo(runs));
            foreach (TransitionPlayer p in crowd.Players)
            {
                Assert.That(p.HeldFrames, Is.EqualTo(0));
                Assert.That(p.Correction, Is.EqualTo(0));
            }
        }

        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void APlayingCrowdAllocatesNothingPerFrame()
        {
            using var crowd = new Crowd(new MainThreadScheduler(OnnxRuntimeInbetweener.Load(Fixtures.TinyModel, requireLazy: true)), 16, seed: 5);
            // A first round creates the jobs, batch tensors and bindings; the second is the steady state.
            crowd.PlayUntil(0.5);
            crowd.RequestAll();
            crowd.PlayUntil(2.0);
            crowd.RequestAll();
            crowd.Step();
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 40; i++) crowd.Step();
            long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.That(bytes, Is.EqualTo(0), "bytes allocated over 40 frames of 16 playing characters");
        }

        [TestCase(0)]
        [TestCase(3)]
        public void OnADeviceBackendKeyMemoryNeverCrossesToTheHostAndResultsEqualTheHostPath(int latencyFrames)
        {
            using var host = new Crowd(new MainThreadScheduler(StandInInbetweener(latencyFrames, out StandInBackend[] h)), 12, seed: 6);
            using var device = new Crowd(new MainThreadScheduler(StandInInbetweener(latencyFrames, out StandInBackend[] d, device: true)), 12, seed: 6);
            BatchPump scheduler = ((MainThreadScheduler)device.Scheduler).Batches;
            Assert.That(scheduler.KeepsKeyMemoryOnDevice, Is.True);
            Assert.That(((MainThreadScheduler)host.Scheduler).Batches.KeepsKeyMemoryOnDevice, Is.False);
            long reads = h[1].KeyMemoryHostReads + d[1].KeyMemoryHostReads, uploads = h[2].KeyMemoryHostUploads + d[2].KeyMemoryHostUploads;
            Assert.That(reads, Is.EqualTo(2), "each model's load-time probe (constant outputs) ran the keys graph once on the host");
            Assert.That(uploads, Is.EqualTo(2), "and the frame graph");
            foreach (Crowd c in new[] { host, device })
            {
                c.PlayUntil(0.5);
                c.RequestAll();
                c.PlayUntil(0.6);
                // Superseded rows of the first keys runs: their frames are computed with the others' and ignored.
                c.RequestAll(i => i % 2 == 0);
                c.PlayUntil(0.8);
                c.RequestAll(i => i % 3 == 0);
                c.PlayUntil(0.85);
                if (c == device) Assert.That(scheduler.DeviceRunsHeld, Is.GreaterThan(1), "several keys runs held on the device at once");
                c.PlayUntil(2.5);
            }

            for (int i = 0; i < host.Players.Count; i++)
            {
                TransitionRequest x = host.Players[i].CurrentRequest!, y = device.Players[i].CurrentRequest!;
                Assert.That(y.Decoded, Is.EqualTo(y.Transition.MissingFrames), $"character {i}: every frame decoded");
                Assert.That(MaxAbs(x.Transition.LocalRotations, y.Transition.LocalRotations), Is.LessThan(1e-5), $"character {i}: device vs host key memory");
                Assert.That(MaxAbsValues(x.Transition.RootPositions, y.Transition.RootPositions), Is.LessThan(1e-5 / 0.01), $"character {i}: root positions");
                Assert.That(device.Players[i].HeldFrames, Is.EqualTo(0), "never a frozen frame");
            }

            // Frames of a keys run start as soon as it is encoded (not after the last frame run of its group): never later than on the host path.
            int lateHost = 0, lateDevice = 0;
            for (int i = 0; i < host.Players.Count; i++)
            {
                lateHost += host.Players[i].LateModelFrames;
                lateDevice += device.Players[i].LateModelFrames;
            }

            Assert.That(lateDevice, Is.LessThanOrEqualTo(lateHost), "late model frames, device vs host path");
            TestContext.Out.WriteLine($"late model frames: host {lateHost}, device {lateDevice}");

            Assert.That(h[1].KeyMemoryHostReads, Is.GreaterThan(1), "the host path reads key_memory back (the counter counts)");
            Assert.That(h[2].KeyMemoryHostUploads, Is.GreaterThan(1), "and uploads it for frame runs");
            Assert.That(d[1].Runs, Is.GreaterThan(1));
            Assert.That(d[2].Runs, Is.GreaterThan(1));
            Assert.That(d[1].KeyMemoryHostReads, Is.EqualTo(1), "no key_memory read back to the host after the probe");
            Assert.That(d[2].KeyMemoryHostUploads, Is.EqualTo(1), "no key_memory uploaded from the host after the probe");
            var keys = (DeviceStandInBackend)d[1];
            Assert.That(keys.MostDeviceTensorsHeld, Is.GreaterThan(1));
            Assert.That(scheduler.DeviceRunsHeld, Is.EqualTo(0), "every keys run released once its rows stopped playing");
            Assert.That(keys.DeviceTensorsHeld, Is.EqualTo(0), "and its device tensor with it");
        }

        [Test]
        public void OnADeviceBackendAWorkerThreadDecodesTheSameFrames()
        {
            // WorkerThreadScheduler runs bindings synchronously (Run, then TakeOutput) on its own thread.
            using var host = new Crowd(new WorkerThreadScheduler(StandInInbetweener(0, out _)), 8, seed: 7);
            using var device = new Crowd(new WorkerThreadScheduler(StandInInbetweener(0, out StandInBackend[] d, device: true)), 8, seed: 7);
            foreach (Crowd c in new[] { host, device })
            {
                c.PlayUntil(0.5);
                c.RequestAll();
                foreach (TransitionPlayer p in c.Players) Assert.That(p.WaitUntilDecoded(10000), Is.True);
            }

            for (int i = 0; i < host.Players.Count; i++)
            {
                TransitionRequest x = host.Players[i].CurrentRequest!, y = device.Players[i].CurrentRequest!;
                Assert.That(MaxAbs(x.Transition.LocalRotations, y.Transition.LocalRotations), Is.LessThan(1e-5), $"character {i}");
            }

            Assert.That(d[1].KeyMemoryHostReads + d[2].KeyMemoryHostUploads, Is.EqualTo(2), "the load-time probe's only");
            device.PlayUntil(2.0);
            Assert.That(((DeviceStandInBackend)d[1]).DeviceTensorsHeld, Is.EqualTo(0), "released once played");
        }

        [Test]
        [Retry(5)] // the runtime now and then adds a few KB to this thread's count at a random frame (seen with no GC and with tiering off); bytes our code allocates repeat in every attempt
        public void OnADeviceBackendAPlayingCrowdAllocatesNothingPerFrame()
        {
            using var crowd = new Crowd(new MainThreadScheduler(StandInInbetweener(2, out StandInBackend[] d, device: true)), 16, seed: 5);
            crowd.PlayUntil(0.5);
            crowd.RequestAll();
            crowd.PlayUntil(2.0);
            // The second round reuses the first's keys runs (tensors, bindings, device buffers); its keys run
            // (latency 2) completes within the frames measured. The first frame after a request is not measured,
            // as with ONNX Runtime above (the players' own first frame of a transition).
            crowd.RequestAll();
            crowd.Step();
            BatchPump scheduler = ((MainThreadScheduler)crowd.Scheduler).Batches;
            Assert.That(scheduler.DeviceRunsHeld, Is.EqualTo(0), "the keys run is still in flight");
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 40; i++) crowd.Step();
            long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
            Assert.That(bytes, Is.EqualTo(0), "bytes allocated over 40 frames of 16 playing characters");
            Assert.That(d[1].Runs, Is.GreaterThan(2));
            Assert.That(scheduler.KeepsKeyMemoryOnDevice, Is.True);
        }

        private static string V1Model => System.IO.Path.Combine(Fixtures.Directory, "tiny-model-v1.onnx");

        private static double[] At(TransitionRequest job, double u, bool model)
        {
            var t = job.Transition;
            int g = t.MissingFrames + 1;
            int jr = 4 * t.Skeleton.JointCount;
            int a = Math.Min((int)Math.Floor(u), g - 1);
            double f = u - a;
            double[] Frame(int i, out int offset)
            {
                if (i == 0 || i == g)
                {
                    offset = jr * (i == 0 ? t.PastFrames - 1 : t.PastFrames);
                    return t.KeyLocalRotations;
                }

                offset = jr * (i - 1);
                return model ? t.LocalRotations : job.SlerpRotations;
            }

            double[] pa = Frame(a, out int oa), pb = Frame(a + 1, out int ob);
            var result = new double[jr];
            for (int j = 0; j < jr; j += 4)
            {
                Quaternions.Normalize(Quaternions.Slerp(QuaternionD.Read(pa, oa + j), QuaternionD.Read(pb, ob + j), f)).Write(result, j);
            }

            return result;
        }

        private static double MaxAngle(double[] a, double[] b)
        {
            double max = 0;
            for (int j = 0; j < a.Length / 4; j++) max = Math.Max(max, EaseIn.Angle(a, b, j));
            return max;
        }

        private static double MaxAbsValues(double[] a, double[] b)
        {
            double max = 0;
            for (int i = 0; i < a.Length; i++) max = Math.Max(max, Math.Abs(a[i] - b[i]));
            return max;
        }

        private static double MaxAbs(double[] a, double[] b)
        {
            double max = 0;
            for (int i = 0; i < a.Length; i += 4)
            {
                // q and −q are the same rotation.
                double same = 0, flipped = 0;
                for (int c = 0; c < 4; c++)
                {
                    same = Math.Max(same, Math.Abs(a[i + c] - b[i + c]));
                    flipped = Math.Max(flipped, Math.Abs(a[i + c] + b[i + c]));
                }

                max = Math.Max(max, Math.Min(same, flipped));
            }

            return max;
        }

        /// <summary>The tiny model's contract on <see cref="StandInBackend"/>s: [whole, keys, frame].</summary>
        internal static Inbetweener StandInInbetweener(int latencyFrames, out StandInBackend[] graphs, bool device = false)
        {
            var descriptions = new ModelDescription[3];
            string[] files = { Fixtures.TinyModel, Fixtures.TinyModel.Replace(".onnx", ".keys.onnx"), Fixtures.TinyModel.Replace(".onnx", ".frame.onnx") };
            for (int i = 0; i < 3; i++)
            {
                using OnnxRuntimeBackend real = OnnxRuntimeBackend.Load(files[i]);
                descriptions[i] = real.Description;
            }

            graphs = device
                ? new StandInBackend[] { new DeviceStandInBackend(descriptions[0], latencyFrames), new DeviceStandInBackend(descriptions[1], latencyFrames), new DeviceStandInBackend(descriptions[2], latencyFrames) }
                : new[] { new StandInBackend(descriptions[0], latencyFrames), new StandInBackend(descriptions[1], latencyFrames), new StandInBackend(descriptions[2], latencyFrames) };
            return new Inbetweener(graphs[0], graphs[1], graphs[2]);
        }

        /// <summary>N characters playing their own clips on one scheduler, stepped together at 60 fps.</summary>
        private sealed class Crowd : IDisposable
        {
            private readonly List<SyntheticClip> _clips = new List<SyntheticClip>();
            private readonly List<PlayingCharacter> _characters = new List<PlayingCharacter>();
            private readonly int _seed;

            public Crowd(TransitionScheduler scheduler, int characters, int seed, PlaybackSettings? settings = null)
            {
                Scheduler = scheduler;
                _seed = seed;
                ModelContract c = scheduler.Contract;
                Map = new NamePoseConverter(c.Skeleton, c.UnitScale, c.Skeleton.Names);
                for (int i = 0; i < characters; i++)
                {
                    // Past frames mixed the way a game mixes them: most characters with full history, some short.
                    // Feet unlocked: these tests hold shown poses to the request's exact SLERP and network frames
                    // (locking after the ease-in has tests of its own).
                    var s = settings ?? new PlaybackSettings { BlendInSeconds = 0, PastFrames = i % 4 == 3 ? 4 : 0, LockFeet = false };
                    var clip = new SyntheticClip(c.JointCount, seed * 1000 + i);
                    var character = new PlayingCharacter(Map, scheduler, s, clip.Sample);
                    _clips.Add(clip);
                    _characters.Add(character);
                    Players.Add(character.Player);
                }
            }

            public TransitionScheduler Scheduler { get; }

            public NamePoseConverter Map { get; }

            public List<TransitionPlayer> Players { get; } = new List<TransitionPlayer>();

            /// <summary>The characters' clock (they all step together): the last frame's time.</summary>
            public double Time => _characters[0].Time;

            public double RequestTime { get; private set; }

            private int _round;

            /// <summary>One rendered frame: the frame's owner pumps the scheduler once, then every character's frame.</summary>
            public void Step()
            {
                Scheduler.Pump();
                for (int i = 0; i < _characters.Count; i++) _characters[i].Frame(1 / Fps);
            }

            public void PlayUntil(double time)
            {
                while (Time + 1 / Fps <= time + 1e-9) Step();
            }

            /// <summary>Every character (or those <paramref name="which"/> picks) asks for a transition in the same frame (durations 0.4–0.8 s, varied per character).</summary>
            public void RequestAll(Predicate<int>? which = null)
            {
                _round++;
                RequestTime = Time;
                var root = new double[3];
                var rotations = new double[4 * Map.BoneCount];
                for (int i = 0; i < Players.Count; i++)
                {
                    if (which != null && !which(i)) continue;
                    _clips[i].Sample(Time + 3 + i * 0.1 + _round, root, rotations);
                    _characters[i].RequestTransition(root, rotations, 0.4 + 0.1 * ((i + _seed) % 5));
                }
            }

            public void Dispose() => Scheduler.Dispose();
        }
    }

    /// <summary>
    /// A stand-in inference engine with a known cost and latency: it answers the graphs of the contract
    /// with smooth made-up numbers that depend on each row's inputs only, counts rows and tokens, and
    /// (as a GPU would) finishes a scheduled run only after <c>latency</c> polls. It also counts every time
    /// <c>key_memory</c> crosses between host and engine: a keys run that writes it into Core's array, a frame
    /// run that reads it from there.
    /// </summary>
    internal class StandInBackend : IInferenceBackend
    {
        private readonly int _latency;

        public StandInBackend(ModelDescription description, int latency)
        {
            Description = description;
            _latency = latency;
        }

        public ModelDescription Description { get; }

        public long Runs { get; private set; }

        public long Tokens { get; private set; }

        /// <summary>Runs that wrote <c>key_memory</c> into a host array (the keys graph read back).</summary>
        public long KeyMemoryHostReads { get; private set; }

        /// <summary>Runs that read <c>key_memory</c> from a host array (the frame graph's upload).</summary>
        public long KeyMemoryHostUploads { get; private set; }

        public IInferenceBinding Bind(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs) => new Binding(this, inputs, outputs, null);

        public void Dispose()
        {
        }

        /// <summary>Device memory of <see cref="DeviceStandInBackend"/>: a pooled buffer, known to Core only as a handle.</summary>
        internal sealed class DeviceTensor : IDeviceTensor
        {
            private readonly DeviceStandInBackend _owner;

            public DeviceTensor(DeviceStandInBackend owner, int length)
            {
                _owner = owner;
                Data = new float[length];
            }

            public float[] Data { get; }

            /// <summary>Bumped at every rent: a binding that kept an older lease holds a released tensor.</summary>
            public int Lease { get; set; }

            public bool Held { get; set; }

            public void Dispose()
            {
                if (!Held) throw new InvalidOperationException("device tensor disposed twice");
                Held = false;
                _owner.Return(this);
            }
        }

        protected class Binding : IAsyncInferenceBinding
        {
            private readonly StandInBackend _owner;
            private readonly Dictionary<string, InferenceTensor> _tensors = new Dictionary<string, InferenceTensor>();
            private readonly IReadOnlyList<InferenceTensor> _outputs;
            private int _polls = -1;

            public Binding(StandInBackend owner, IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs, string? onDevice)
            {
                _owner = owner;
                foreach (InferenceTensor t in inputs)
                {
                    owner.Description.RequireInput(t);
                    _tensors[t.Name] = t;
                }

                foreach (InferenceTensor t in outputs)
                {
                    owner.Description.RequireOutput(t);
                    _tensors[t.Name] = t;
                }

                if (onDevice != null && !_tensors.ContainsKey(onDevice)) throw new ArgumentException($"no tensor '{onDevice}' to keep on the device");
                OnDevice = onDevice;
                _outputs = outputs;
            }

            /// <summary>The tensor kept on the device, or null.</summary>
            protected string? OnDevice { get; }

            public void Run()
            {
                Count();
                Compute();
            }

            private void Count()
            {
                _owner.Runs++;
                InferenceTensor gap = _tensors[TensorNames.GapLength];
                int rows = (int)gap.Shape[0];
                if (_tensors.TryGetValue(TensorNames.KeyFeatures, out InferenceTensor? keys)) _owner.Tokens += rows * keys.Shape[1];
                else _owner.Tokens += _tensors[TensorNames.QueryFrameIndices].Length;
            }

            public void Schedule()
            {
                Count();
                Scheduled();
                _polls = 0;
            }

            public bool TryComplete()
            {
                if (_polls < 0) throw new InvalidOperationException("nothing scheduled");
                if (_polls++ < _owner._latency) return false;
                _polls = -1;
                Compute();
                return true;
            }

            public void Dispose()
            {
            }

            /// <summary>What a run does when it is scheduled (device bindings check their input's lease).</summary>
            protected virtual void Scheduled()
            {
            }

            /// <summary>Where a run writes key_memory (null: the bound host array).</summary>
            protected virtual float[]? DeviceOutput(int length) => null;

            /// <summary>Where a run reads key_memory (null: the bound host array).</summary>
            protected virtual float[]? DeviceInput(int length) => null;

            private void Compute()
            {
                long[] gap = _tensors[TensorNames.GapLength].Longs!;
                int rows = (int)_tensors[TensorNames.GapLength].Shape[0];
                bool uploaded = false;
                for (int i = 0; i < _outputs.Count; i++)
                {
                    InferenceTensor o = _outputs[i];
                    switch (o.Name)
                    {
                        case TensorNames.ContractVersion: o.Longs![0] = ModelContract.Version; break;
                        case TensorNames.JointCount: o.Longs![0] = 22; break;
                        case TensorNames.KeyFeatureSize: o.Longs![0] = 198; break;
                        case TensorNames.KeyMemory:
                        {
                            float[] f = _tensors[TensorNames.KeyFeatures].Floats!;
                            int fw = (int)(_tensors[TensorNames.KeyFeatures].Length / rows);
                            int mw = o.Length / rows;
                            float[]? device = OnDevice == o.Name ? DeviceOutput(o.Length) : null;
                            float[] dst = device ?? o.Floats!;
                            if (device == null) _owner.KeyMemoryHostReads++;
                            for (int r = 0; r < rows; r++)
                            {
                                for (int e = 0; e < mw; e++) dst[r * mw + e] = (float)(0.5 * Math.Sin(0.37 * e + 3 * f[r * fw + e % fw] + 0.1 * gap[r]));
                            }

                            break;
                        }

                        case TensorNames.RootPositionDelta:
                        case TensorNames.Rotation6DDelta:
                        {
                            InferenceTensor? memory = _tensors.TryGetValue(TensorNames.KeyMemory, out InferenceTensor? m) ? m : null;
                            float[]? source = null;
                            if (memory != null)
                            {
                                source = OnDevice == memory.Name ? DeviceInput(memory.Length) : null;
                                if (source == null && !uploaded)
                                {
                                    uploaded = true;
                                    _owner.KeyMemoryHostUploads++;
                                }

                                source ??= memory.Floats!;
                            }

                            long[] query = _tensors[TensorNames.QueryFrameIndices].Longs!;
                            int n = (int)(_tensors[TensorNames.QueryFrameIndices].Length / rows);
                            int width = o.Length / (rows * n);
                            for (int r = 0; r < rows; r++)
                            {
                                // Each row's memory decides its frames (its first and a middle element).
                                int mw = memory == null ? 0 : memory.Length / rows;
                                double seed = source == null ? 0 : source[r * mw] + 0.5 * source[r * mw + mw / 2];
                                for (int q = 0; q < n; q++)
                                {
                                    double x = 0.25 * query[r * n + q];
                                    for (int e = 0; e < width; e++)
                                    {
                                        double scale = o.Name == TensorNames.RootPositionDelta ? 0.02 : 0.25;
                                        o.Floats![(r * n + q) * width + e] = (float)(scale * Math.Sin(x + 0.7 * e + seed));
                                    }
                                }
                            }

                            break;
                        }
                    }
                }
            }
        }
    }

    /// <summary>
    /// <see cref="StandInBackend"/> that can keep <c>key_memory</c> on its "device" (<see cref="IDeviceTensorBackend"/>,
    /// as Sentis on a GPU does): pooled buffers behind handles, whose uses after release, double releases, wrong
    /// shapes and leaks the tests see.
    /// </summary>
    internal sealed class DeviceStandInBackend : StandInBackend, IDeviceTensorBackend
    {
        private readonly List<DeviceTensor> _free = new List<DeviceTensor>();

        public DeviceStandInBackend(ModelDescription description, int latency)
            : base(description, latency)
        {
        }

        /// <summary>Device tensors handed to Core and not released yet.</summary>
        public int DeviceTensorsHeld { get; private set; }

        /// <summary>Most device tensors held at once.</summary>
        public int MostDeviceTensorsHeld { get; private set; }

        public IDeviceTensorBinding BindOnDevice(IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs, string onDevice) =>
            new DeviceBinding(this, inputs, outputs, onDevice);

        internal DeviceTensor Rent(int length)
        {
            DeviceTensor? t = null;
            for (int i = 0; i < _free.Count; i++)
            {
                if (_free[i].Data.Length != length) continue;
                t = _free[i];
                _free.RemoveAt(i);
                break;
            }

            t ??= new DeviceTensor(this, length);
            t.Lease++;
            t.Held = true;
            DeviceTensorsHeld++;
            MostDeviceTensorsHeld = Math.Max(MostDeviceTensorsHeld, DeviceTensorsHeld);
            return t;
        }

        internal void Return(DeviceTensor t)
        {
            DeviceTensorsHeld--;
            _free.Add(t);
        }

        private sealed class DeviceBinding : Binding, IDeviceTensorBinding
        {
            private readonly DeviceStandInBackend _owner;
            private DeviceTensor? _input;
            private int _inputLease;
            private DeviceTensor? _output;

            public DeviceBinding(DeviceStandInBackend owner, IReadOnlyList<InferenceTensor> inputs, IReadOnlyList<InferenceTensor> outputs, string onDevice)
                : base(owner, inputs, outputs, onDevice)
            {
                _owner = owner;
            }

            public void SetInput(IDeviceTensor tensor)
            {
                _input = (DeviceTensor)tensor;
                _inputLease = _input.Lease;
            }

            public IDeviceTensor TakeOutput()
            {
                DeviceTensor t = _output ?? throw new InvalidOperationException("no completed run's output to take");
                _output = null;
                return t;
            }

            protected override void Scheduled() => Check();

            protected override float[]? DeviceOutput(int length)
            {
                // An output not taken is released by the next run, as a real engine would reuse it.
                _output?.Dispose();
                _output = _owner.Rent(length);
                return _output.Data;
            }

            protected override float[]? DeviceInput(int length)
            {
                if (_input == null) throw new InvalidOperationException("a run of a device input without SetInput");
                Check();
                if (_input.Data.Length != length) throw new InvalidOperationException($"device key_memory of {_input.Data.Length} elements bound where {length} are expected");
                return _input.Data;
            }

            private void Check()
            {
                if (_input == null) return;
                if (!_input.Held || _input.Lease != _inputLease) throw new InvalidOperationException("the device key_memory was released before the run that reads it completed");
            }
        }
    }
}
