using DeltaInterpolator.Core.Scheduling;
using DeltaInterpolator.Core.Characters;
using System;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>One character's neural transitions in real time: it records the pose shown every rendered frame (<see cref="PoseHistory"/>), turns <see
    /// cref="RequestTransition"/> into a network request at the model's frame rate, and plays the answer at whatever rate the game renders, interpolating
    /// between model frames, blended over the character's own animation. A frame is never frozen: until the network's frames of a request arrive, it shows the request's SLERP pose (the network's own baseline), and the
    /// network's correction eases in when they do (<see cref="Correction"/>).</summary>
    /// <remarks>
    /// <para>Each rendered frame: <see cref="BeginFrame"/>, <see cref="PoseBlend.Apply"/> over the animation stream, then <see cref="Record"/> of the
    /// pose shown (<see cref="Step"/> does the three); <see cref="TransitionCharacter"/> runs a game's whole frame around them.</para>
    /// <para>Time is real. A request of d seconds is G = round(d · fps) model frames (at least 2); its
    /// frames are spread evenly over exactly d seconds from the newest recorded frame t0, so the first
    /// rendered frame at or after t0 + d shows the target pose (weight 1), and
    /// <see cref="TransitionCompleted"/> fires in that frame. Missing frames come from the scheduler;
    /// until the ones a frame needs are there, the frame shows the SLERP pose of the same request.</para>
    /// <para>A request made during a transition starts from the pose being shown (the newest recorded)
    /// at full weight, so the motion stays continuous; the interrupted request completes with
    /// <see cref="TransitionCompletion.ReachedTarget"/> false. After the target, the weight eases back to
    /// the character's animation over <see cref="PlaybackSettings.BlendOutSeconds"/>.</para>
    /// <para>With <see cref="PlaybackSettings.LockFeet"/> (the default) each pose the transition shows has its
    /// planted feet held and its legs solved (<see cref="Feet.LiveFootLocker"/>), after the SLERP → network
    /// ease-in and before it is mapped onto the character.</para>
    /// <para>Main thread only. <see cref="BeginFrame"/>, <see cref="Record"/> and <see cref="Step"/> allocate nothing.</para>
    /// </remarks>
    public sealed class TransitionPlayer
    {
        /// <summary>Frame times within this of the target time count as reaching it (rounding of summed frame times).</summary>
        private const double TimeTolerance = 1e-9;

        private readonly IPoseConverter _map;
        private readonly TransitionScheduler _scheduler;
        private readonly PlaybackSettings _settings;
        // A finished request is free for the next of its shape (the playing one is skipped); non-capturing, so a search allocates nothing.
        private static readonly Func<TransitionRequest, bool> IsFinished = r => r.Finished;
        private readonly ShapeCache<TransitionRequest> _requests = new ShapeCache<TransitionRequest>();
        private readonly int _joints;
        private readonly double[] _pastRoots;
        private readonly double[] _pastRotations;
        private readonly double[] _poseRoot = new double[3];
        private readonly double[] _poseRotations;
        private readonly double[] _targetRoot = new double[3];
        private readonly double[] _targetRotations;
        private readonly double[] _shownRoot = new double[3];
        private readonly double[] _shownRotations;
        private readonly EaseIn _ease;
        private readonly TransitionFeet? _feet;
        private TransitionRequest? _request;
        private int _requestId;
        private int _nextId;
        private bool _playing;
        private bool _reached;
        private bool _inFrame;
        private double _start;
        private double _duration;
        private double _period;
        private double _reachedAt;
        private double _startWeight;
        private double _weight;
        private int _gap;
        private int _neededBefore;
        private CompletionEvents _events;
        private bool _letGo;
        private bool _deferredLetGo;
        private int _letGoArrived;
        private double _letGoLate;
        private int _deferredId;
        private double _deferredArrival;

        /// <summary>Creates a player for one character.</summary>
        /// <param name="map">Character bones ↔ model joints; its joint count must be the model's.</param>
        /// <param name="scheduler">Where the network runs (may be shared by many players of one model).</param>
        /// <param name="settings">Blend times and past frames; read at each request and frame.</param>
        public TransitionPlayer(IPoseConverter map, TransitionScheduler scheduler, PlaybackSettings? settings = null)
        {
            _map = map ?? throw new ArgumentNullException(nameof(map));
            _scheduler = scheduler ?? throw new ArgumentNullException(nameof(scheduler));
            _settings = settings ?? new PlaybackSettings();
            ModelContract c = scheduler.Contract;
            if (map.JointCount != c.JointCount)
            {
                throw new ArgumentException($"the joint map has {map.JointCount} model joints but the model {c.Name} has {c.JointCount}; build the map from this model's skeleton", nameof(map));
            }

            _joints = c.JointCount;
            FrameRate = scheduler.FrameRate;
            PastFrames = _settings.PastFrames > 0 ? _settings.PastFrames : c.TrainingPastFrames.Max;
            if (PastFrames < 1 || PastFrames >= c.MaxFrameIndex) throw new ArgumentOutOfRangeException(nameof(settings), PastFrames, $"past frames must lie in 1..{c.MaxFrameIndex - 1}");
            int b = map.BoneCount;
            History = new PoseHistory(b, FrameRate, PastFrames);
            _pastRoots = new double[PastFrames * 3];
            _pastRotations = new double[PastFrames * b * 4];
            _poseRotations = new double[b * 4];
            _targetRotations = new double[b * 4];
            _shownRotations = new double[b * 4];
            _ease = new EaseIn(_joints);
            _feet = TransitionFeet.For(map, c.Skeleton, FrameRate);
        }

        /// <summary>Reports every request exactly once: when its target pose is shown, or when it is interrupted or cancelled.</summary>
        public event Action<TransitionCompletion>? TransitionCompleted;

        /// <summary>Bones per character pose.</summary>
        public int BoneCount => _map.BoneCount;

        /// <summary>The model's frame rate (contract <c>training.fps</c>).</summary>
        public double FrameRate { get; }

        /// <summary>Past model frames each request feeds the network (P).</summary>
        public int PastFrames { get; }

        /// <summary>The poses shown, recorded each frame.</summary>
        public PoseHistory History { get; }

        /// <summary>True from a request until the weight has eased back to 0 after its target.</summary>
        public bool IsPlaying => _playing;

        /// <summary>The current request's id (0 before the first).</summary>
        public int CurrentRequestId => _requestId;

        /// <summary>The frame time at which the current request shows its target (t0 + duration).</summary>
        public double TargetTime => _start + _duration;

        /// <summary>True from the frame that showed the current request's target until its blend-out ends.</summary>
        public bool HasReachedTarget => _playing && _reached;

        /// <summary>Model frames between the last past key and the target of the current request (G = n + 1).</summary>
        public int GapFrames => _gap;

        /// <summary>This frame's transition weight (0: the character's own animation, 1: the transition's pose).</summary>
        public double Weight => _weight;

        /// <summary>This frame's transition root position (character space, 3 values).</summary>
        public ReadOnlySpan<double> PoseRoot => _poseRoot;

        /// <summary>This frame's transition local rotations (character space, bones × 4, w x y z).</summary>
        public ReadOnlySpan<double> PoseRotations => _poseRotations;

        /// <summary>The root position shown by the last <see cref="Step"/> (character space).</summary>
        public ReadOnlySpan<double> ShownRoot => _shownRoot;

        /// <summary>The local rotations shown by the last <see cref="Step"/> (character space).</summary>
        public ReadOnlySpan<double> ShownRotations => _shownRotations;

        /// <summary>The current request's network problem (keys and missing frames, model space), or null.</summary>
        public Transition? CurrentTransition => _request?.Transition;

        /// <summary>The current request's request (SLERP and network frames), for tests and tools.</summary>
        internal TransitionRequest? CurrentRequest => _request;

        /// <summary>The foot locker of this character's transitions (null when the model's skeleton lacks leg joints), for tests and tools.</summary>
        internal LiveFootLocker? Feet => _feet?.Locker;

        /// <summary>Missing frames of the current request decoded so far.</summary>
        public int DecodedFrames => _request?.Decoded ?? 0;

        /// <summary>The model checks of a request lasting <paramref name="durationSeconds"/> from now: P past frames and the gap it becomes at the model's
        /// frame rate, outside the ranges the model was trained on, are warnings (it runs, but was never taught such requests); see <see
        /// cref="ModelChecks.Request"/>.</summary>
        public ModelCheckReport CheckRequest(double durationSeconds) => RequestChecks.Report(_scheduler.Contract, PastFrames, FrameRate, durationSeconds, MissingFramesFor(durationSeconds));

        // Model frames of a duration counted in double: a duration of 1e8 s is 3e9 frames, beyond int (whose cast
        // wrapped round to a short gap that passed every check); capped, as anything past the model's span is refused.
        private int MissingFramesFor(double durationSeconds) =>
            (int)Math.Max(2, Math.Min(Math.Round(durationSeconds * FrameRate), _scheduler.Contract.MaxFrameIndex + 2.0)) - 1;

        /// <summary>How much of the network's correction this frame shows over the request's SLERP pose (0: SLERP only, while the network's frames have not
        /// arrived or with <see cref="PlaybackSettings.SlerpOnly"/>; 1: the network's pose). It rises when the frames arrive as fast as keeps every joint's
        /// turn between two shown frames within 1.2 × the larger of SLERP's and the network's own turn there, plus 0.45°.</summary>
        public double Correction => _ease.Weight;

        /// <summary>Model frames, over all requests, that playback needed before the network had decoded them (each was shown as SLERP).</summary>
        public int LateModelFrames { get; private set; }

        /// <summary>Rendered frames, over all requests, whose transition pose was the previous frame's although time moved on (a frozen frame); 0 by design.</summary>
        public int HeldFrames { get; private set; }

        /// <summary>Asks for a transition from the pose shown now to <paramref name="targetRotations"/> in <paramref name="durationSeconds"/>. The network's
        /// inputs are built here (history resampled at the model's rate, converted to the model's space); the network runs on the scheduler.</summary>
        /// <param name="targetRoot">Target root position (character space, 3 values).</param>
        /// <param name="targetRotations">Target local rotations (character space, bones × 4, w x y z).</param>
        /// <param name="durationSeconds">Seconds from the newest recorded frame to the target.</param>
        /// <returns>The request's id, as reported by <see cref="TransitionCompleted"/>.</returns>
        /// <exception cref="InvalidOperationException">No frame was recorded yet.</exception>
        /// <exception cref="ArgumentOutOfRangeException">The duration is not positive or longer than the model can span.</exception>
        public int RequestTransition(ReadOnlySpan<double> targetRoot, ReadOnlySpan<double> targetRotations, double durationSeconds)
        {
            if (targetRoot.Length < 3 || targetRotations.Length < 4 * BoneCount) throw new ArgumentException($"a target pose needs 3 root values and {4 * BoneCount} rotation values");
            RequestChecks.CheckFinite(targetRoot.Slice(0, 3), targetRotations.Slice(0, 4 * BoneCount), "target", nameof(targetRoot), nameof(targetRotations));
            int missing = CheckRequestable(durationSeconds);
            // A newer request replaces one still waiting for its target pose.
            DropDeferred();
            return Start(targetRoot, targetRotations, durationSeconds, missing, ++_nextId, false);
        }

        /// <summary>Asks for a transition whose target pose is not known yet: the animation system samples it (Unity: a clip through the playable graph, at its
        /// next evaluation) and <see cref="CompleteDeferredTransition"/> hands it over. The transition arrives when it would have if the pose had been given
        /// now (<paramref name="durationSeconds"/> from the newest recorded frame); until the pose comes, the current transition (if any) plays on. A newer
        /// request, deferred or not, and <see cref="Cancel"/> end it (reported with ReachedTarget false).</summary>
        /// <returns>The request's id, as reported by <see cref="TransitionCompleted"/>.</returns>
        /// <exception cref="InvalidOperationException">No frame was recorded yet.</exception>
        /// <exception cref="ArgumentOutOfRangeException">The duration is not positive or longer than the model can span.</exception>
        public int DeferTransition(double durationSeconds) => Defer(durationSeconds, false);

        /// <summary><see cref="DeferTransition"/> as a hand-off: the transition starts from the pose shown at full
        /// weight (the controller's old motion is not blended in, as nothing returns to it) and lets go in the frame it arrives (weight 0 from then on, no
        /// blend-out), when the controller shows the target state itself (<see cref="TransitionCharacter.RequestState"/>, <see cref="AnimatorTransitions"/>).</summary>
        /// <returns>The request's id, as reported by <see cref="TransitionCompleted"/>.</returns>
        /// <exception cref="InvalidOperationException">No frame was recorded yet.</exception>
        /// <exception cref="ArgumentOutOfRangeException">The duration is not positive or longer than the model can span.</exception>
        public int DeferHandOff(double durationSeconds) => Defer(durationSeconds, true);

        private int Defer(double durationSeconds, bool letGoOnArrival)
        {
            CheckRequestable(durationSeconds);
            DropDeferred();
            _deferredId = ++_nextId;
            _deferredLetGo = letGoOnArrival;
            _deferredArrival = History.NewestTime + durationSeconds;
            FlushEvents();
            return _deferredId;
        }

        /// <summary>The id of the request waiting for its target pose (0: none), and the frame time it arrives at (the engine samples where the character will be then).</summary>
        public int DeferredRequestId => _deferredId;

        /// <inheritdoc cref="DeferredRequestId"/>
        public double DeferredArrivalTime => _deferredArrival;

        /// <summary>True when the current request lets go on arrival (a hand-off) rather than blending out.</summary>
        public bool LetsGoOnArrival => _letGo;

        // The hand-off request that arrived in this frame (0: none), and how late its frame came after the target time.
        internal int LetGoArrivedId => _letGoArrived;
        internal double LetGoLateSeconds => _letGoLate;

        /// <summary>The model's contract (trained gaps, span), for the types that decide what to request.</summary>
        internal ModelContract Contract => _scheduler.Contract;

        /// <summary>True while a <see cref="DeferTransition"/> request waits for its target pose.</summary>
        public bool HasDeferredTransition => _deferredId != 0;

        /// <summary>Starts the waiting <see cref="DeferTransition"/> request with its target pose (same spaces as <see cref="RequestTransition"/>): it arrives
        /// at the time asked for when it was deferred, or one model frame after the newest recorded frame when the pose came later than that.</summary>
        /// <returns>The deferred request's id.</returns>
        /// <exception cref="InvalidOperationException">No request is waiting.</exception>
        public int CompleteDeferredTransition(ReadOnlySpan<double> targetRoot, ReadOnlySpan<double> targetRotations)
        {
            if (_deferredId == 0) throw new InvalidOperationException("no deferred transition is waiting for its target pose");
            if (targetRoot.Length < 3 || targetRotations.Length < 4 * BoneCount) throw new ArgumentException($"a target pose needs 3 root values and {4 * BoneCount} rotation values");
            RequestChecks.CheckFinite(targetRoot.Slice(0, 3), targetRotations.Slice(0, 4 * BoneCount), "target", nameof(targetRoot), nameof(targetRotations));
            int id = _deferredId;
            _deferredId = 0;
            double duration = Math.Max(_deferredArrival - History.NewestTime, 1.0 / FrameRate);
            return Start(targetRoot, targetRotations, duration, MissingFramesFor(duration), id, _deferredLetGo);
        }

        // The duration's missing frames, after the checks every request passes.
        private int CheckRequestable(double durationSeconds)
        {
            if (!(durationSeconds > 0) || double.IsInfinity(durationSeconds)) throw new ArgumentOutOfRangeException(nameof(durationSeconds), durationSeconds, "expected a positive number of seconds");
            if (History.Count == 0) throw new InvalidOperationException("no frame has been recorded yet: play at least one frame before requesting a transition");
            string? tooLong = RequestChecks.TooLong(_scheduler.Contract, PastFrames, FrameRate, durationSeconds);
            if (tooLong != null) throw new ArgumentOutOfRangeException(nameof(durationSeconds), durationSeconds, tooLong);
            return MissingFramesFor(durationSeconds);
        }

        private void DropDeferred()
        {
            if (_deferredId == 0) return;
            _events.Dropped(_deferredId, History.Count == 0 ? 0 : History.NewestTime);
            _deferredId = 0;
        }

        private int Start(ReadOnlySpan<double> targetRoot, ReadOnlySpan<double> targetRotations, double durationSeconds, int missing, int id, bool letGo)
        {
            int gap = missing + 1;
            bool wasPlaying = _playing;
            Interrupt(History.NewestTime);
            TransitionRequest request = RequestFor(PastFrames, missing);
            Transition t = request.Transition;
            double t0 = History.NewestTime;
            History.Resample(t0, PastFrames, _pastRoots, _pastRotations);
            int r = 4 * BoneCount;
            int jr = 4 * _joints;
            for (int i = 0; i < PastFrames; i++)
            {
                _map.ToModel(new ReadOnlySpan<double>(_pastRoots, 3 * i, 3), new ReadOnlySpan<double>(_pastRotations, r * i, r),
                    new Span<double>(t.KeyRootPositions, 3 * i, 3), new Span<double>(t.KeyLocalRotations, jr * i, jr));
            }

            _map.ToModel(targetRoot, targetRotations, new Span<double>(t.KeyRootPositions, 3 * PastFrames, 3), new Span<double>(t.KeyLocalRotations, jr * PastFrames, jr));
            targetRoot.Slice(0, 3).CopyTo(_targetRoot);
            targetRotations.Slice(0, r).CopyTo(_targetRotations);
            if (!_inFrame)
            {
                // Until the next frame: the pose shown (the transition's frame 0).
                new ReadOnlySpan<double>(_pastRoots, 3 * (PastFrames - 1), 3).CopyTo(_poseRoot);
                new ReadOnlySpan<double>(_pastRotations, r * (PastFrames - 1), r).CopyTo(_poseRotations);
            }

            // The SLERP frames are known now; the network's correction follows when the scheduler has run.
            _scheduler.Prepare(request);
            if (_settings.SlerpOnly)
            {
                request.Reset();
                request.Finish();
            }
            else
            {
                _scheduler.Start(request);
            }

            _ease.Begin(t);
            if (_settings.LockFeet && _feet != null)
            {
                _feet.Begin(t, PastFrames - 1, PastFrames, t0, t0 + durationSeconds);
            }

            _neededBefore = 0;
            _request = request;
            _requestId = id;
            _playing = true;
            _reached = false;
            _start = t0;
            _duration = durationSeconds;
            _gap = gap;
            _period = durationSeconds / gap;
            // A first request eases in from the character's animation; one during a transition starts from
            // the pose shown at full weight, which is continuous because the new keys end at that pose.
            // A hand-off starts at full weight too: the controller's old motion is not blended in, nothing returns to it.
            _startWeight = wasPlaying || letGo ? 1.0 : 0.0;
            _letGo = letGo;
            FlushEvents();
            return _requestId;
        }

        /// <summary>Stops the current transition at once (weight 0); it, and a request still waiting for its target pose, complete with ReachedTarget false.</summary>
        public void Cancel()
        {
            DropDeferred();
            Interrupt(History.Count == 0 ? 0 : History.NewestTime);
            _weight = 0;
            FlushEvents();
        }

        /// <summary>Computes the transition's pose and weight for the frame rendered at <paramref name="time"/> (<see cref="PoseRoot"/>, <see
        /// cref="PoseRotations"/>, <see cref="Weight"/>) and fires <see cref="TransitionCompleted"/> when this frame shows the target.</summary>
        /// <exception cref="InferenceFailedException">The network failed on the scheduler; the transition is ended.</exception>
        public void BeginFrame(double time)
        {
            _inFrame = true;
            _letGoArrived = 0;
            try
            {
                Advance(time);
                FlushEvents();
            }
            finally
            {
                _inFrame = false;
            }
        }

        /// <summary>Records the pose shown at <paramref name="time"/> (character space) into <see cref="History"/>.</summary>
        /// <exception cref="ArgumentException">The pose holds a value that is not finite (NaN or infinity): it is not recorded, so no request is built from it.</exception>
        public void Record(double time, ReadOnlySpan<double> shownRoot, ReadOnlySpan<double> shownRotations)
        {
            RequestChecks.CheckFinite(shownRoot.Slice(0, Math.Min(3, shownRoot.Length)), shownRotations.Slice(0, Math.Min(4 * BoneCount, shownRotations.Length)), "pose shown", nameof(shownRoot), nameof(shownRotations));
            History.Record(time, shownRoot, shownRotations);
        }

        /// <summary>One rendered frame in one call: <see cref="BeginFrame"/>, <see cref="PoseBlend.Apply"/> over <paramref name="stream"/>, and <see
        /// cref="Record"/> of the pose shown.</summary>
        public void Step<TStream>(double time, ref TStream stream)
            where TStream : IPoseStream
        {
            BeginFrame(time);
            PoseBlend.Apply(ref stream, _weight, _poseRoot, _poseRotations, _shownRoot, _shownRotations);
            Record(time, _shownRoot, _shownRotations);
        }

        /// <summary>Blocks until the current request's frames are all decoded (or <paramref name="millisecondsTimeout"/> passes). Games never need this; it
        /// makes cut-scenes and tests deterministic.</summary>
        /// <returns>True when every frame is decoded (or nothing is playing).</returns>
        public bool WaitUntilDecoded(int millisecondsTimeout)
        {
            TransitionRequest? request = _request;
            if (request == null || !_playing || _settings.SlerpOnly) return true;
            return _scheduler.Drain(request, millisecondsTimeout);
        }

        private void Advance(double time)
        {
            if (!_playing || _request == null)
            {
                _weight = 0;
                return;
            }

            TransitionRequest request = _request;
            if (request.Error != null)
            {
                Exception error = request.Error;
                Interrupt(time);
                _weight = 0;
                // The request is reported (not reached) before the failure propagates: every request completes once.
                FlushEvents();
                throw new InferenceFailedException(error);
            }

            double s = time - _start;
            if (s >= _duration - TimeTolerance || _reached)
            {
                if (!_reached)
                {
                    _reached = true;
                    _reachedAt = time;
                    _feet?.Locker.End();
                    _targetRoot.CopyTo(_poseRoot, 0);
                    _targetRotations.CopyTo(_poseRotations, 0);
                    _events.Reached(_requestId, time);
                    _weight = 1;
                    if (!_letGo) return;
                    // A hand-off: the controller shows the target itself from this frame on (no blend-out, nothing returns to the old motion).
                    _letGoArrived = _requestId;
                    _letGoLate = time - (_start + _duration);
                    _playing = false;
                    _weight = 0;
                    return;
                }

                double blendOut = _settings.BlendOutSeconds;
                double x = blendOut > 0 ? (time - _reachedAt) / blendOut : 1;
                if (x >= 1)
                {
                    _playing = false;
                    _weight = 0;
                    return;
                }

                _weight = 1 - SmoothStep(x);
                return;
            }

            double u = Math.Max(0, s) / _period;
            int a = Math.Min((int)Math.Floor(u), _gap - 1);
            double f = u - a;
            int need = Math.Min(a + 1, _gap - 1);
            TransitionScheduler.Need(request, need);
            int decoded = request.Decoded;
            if (need > _neededBefore)
            {
                // Frames playback reaches now that the network has not answered yet: shown as SLERP.
                if (decoded < need && !_settings.SlerpOnly) LateModelFrames += need - Math.Max(decoded, _neededBefore);
                _neededBefore = need;
            }

            if (_ease.Show(request, a, f, decoded >= need)) HeldFrames++;
            // Feet after the SLERP → network ease-in, on the pose about to be shown (model space).
            if (_feet != null) _feet.LockAndShow(time, request, a, f, _ease.Root, _ease.Rotations, _poseRoot, _poseRotations);
            else _map.ToCharacter(_ease.Root, _ease.Rotations, _poseRoot, _poseRotations);
            double blendIn = Math.Min(_settings.BlendInSeconds, _duration);
            double w = blendIn > 0 ? SmoothStep(Math.Max(0, s) / blendIn) : 1;
            _weight = _startWeight + (1 - _startWeight) * w;
        }

        private void Interrupt(double time)
        {
            _feet?.Locker.End();
            if (_request != null) _request.Cancel();
            if (_playing && !_reached) _events.Interrupted(_requestId, time);
            _playing = false;
        }

        private void FlushEvents() => _events.Flush(TransitionCompleted);

        private TransitionRequest RequestFor(int past, int missing)
        {
            return _requests.Find(past, missing, _request, IsFinished)
                ?? _requests.Add(past, missing, new TransitionRequest(new Transition(_scheduler.Contract.Skeleton, past, missing), _scheduler.Contract));
        }

        private static double SmoothStep(double x)
        {
            if (x <= 0) return 0;
            if (x >= 1) return 1;
            return x * x * (3 - 2 * x);
        }
    }
}
