using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Inference;
using Unity.Profiling;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Experimental.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Neural transitions for a character: call <see cref="RequestTransition(AnimationClip, float, float)"/>
    /// (or with a pose) and the character moves from the pose it shows now to the target through frames
    /// that the in-betweening model fills, arriving on the first rendered frame at or after the requested
    /// time; then its own animation takes back over. Plays as an animation job layered after the Animator
    /// Controller, so it composes with whatever the controller does.
    /// </summary>
    /// <remarks>
    /// Thin glue over Core's <see cref="TransitionPlayer"/>: each frame <c>Update</c> records the pose shown
    /// last frame and computes this frame's transition pose; the job blends it over the controller's output.
    /// The network runs on a worker thread when the engine allows it, otherwise lazily on the main thread.
    /// The settings choose the rig (<see cref="InbetweenerSettings.Rig"/>): a humanoid avatar's bones and
    /// T-pose, or a generic rig's bones by a joint map and a reference pose; Core's <see cref="CharacterRig"/>
    /// maps them onto the model's skeleton (handedness, units, bone axes, joints the rig lacks) and refuses,
    /// at start, bones it cannot map or a reference pose that is not a T-pose. Bones the model does not know
    /// (fingers, twist bones) keep the character's own animation. With <c>Animator.applyRootMotion</c> on, a
    /// transition moves the character through the root motion (the stream's velocity) along the model's
    /// root trajectory (Core's <see cref="RootMotion"/>); off, it moves the root bone inside the character.
    /// <para>Transitions run on the Animator's clock (<c>Animator.updateMode</c>, Core's <see cref="AnimationClock"/>):
    /// Normal in scaled time (they freeze with <c>Time.timeScale = 0</c>), Fixed in physics steps, UnscaledTime
    /// in real time. Settings may arrive after the component is added or enabled, and edits to them in play mode
    /// apply (blend times at once, the rest by re-initialising). When the inference engine fails while playing,
    /// the component logs one error naming the model and what to do, and disables itself (Core's <see cref="PlaybackStatus"/>).</para>
    /// </remarks>
    [RequireComponent(typeof(Animator))]
    [DisallowMultipleComponent]
    [AddComponentMenu("Δ-Interpolator/Motion Inbetweener")]
    public sealed class MotionInbetweener : MonoBehaviour
    {
        [SerializeField]
        [Tooltip("Model, inference engine, joint names and blend times.")]
        private InbetweenerSettings? settings = null;

        private Animator? _animator;
        private TransitionDecoder? _decoder;
        private TransitionPlayer? _player;
        private Transform[] _bones = new Transform[0];
        private PlayableGraph _graph;
        private NativeArray<TransformStreamHandle> _handles;
        private NativeArray<double> _pose;
        private NativeArray<double> _shown;
        private NativeArray<double> _weight;
        private double[] _targetRoot = new double[3];
        private double[] _targetRotations = new double[0];
        private ClipTargetSampler? _targetSampler;
        private RootFrame _deferredFrame;
        private RootMotion? _rootMotion;
        // [0..2] the transition's root velocity (main thread → job), [3..5] the controller's (job → main thread), [6] 1 with root motion on.
        private NativeArray<double> _rootVelocity;
        private double[] _recordRoot = new double[3];
        private double[] _recordRotations = new double[0];
        private double _shownTime;
        private bool _shownPending;
        private readonly AnimationClock _clock = new AnimationClock();
        private readonly PlaybackStatus _status = new PlaybackStatus();
        private PlaybackSettings? _playback;
        private SettingsSnapshot? _built;
        private InbetweenerSettings? _listening;
        private bool _isEnabled;
        private bool _settingsChanged;
        private string _modelName = "";
        private string _engineName = "";

        /// <summary>
        /// The sorting order of the component's animation output: after the Animator Controller (whose output
        /// sorts at 0) and before IK and constraint layers such as Animation Rigging's (its RigBuilder sorts at
        /// 1000), so rigs constrain the transition's pose rather than being overwritten by it.
        /// </summary>
        public const ushort LayerSortingOrder = 500;

        /// <summary>Reports each request once: when the character shows its target, or when a newer request or <see cref="Cancel"/> ends it first.</summary>
        public event Action<TransitionCompletion>? TransitionCompleted;

        /// <summary>
        /// The settings asset. May be assigned at any time (e.g. after <c>AddComponent</c>): an enabled component
        /// initialises from it at once; a different asset re-initialises it.
        /// </summary>
        public InbetweenerSettings? Settings
        {
            get => settings;
            set
            {
                if (settings == value) return;
                settings = value;
                if (_isEnabled) Rebuild();
            }
        }

        /// <summary>Waiting (no settings yet), running, or failed (the Console shows why); see <see cref="FailureReason"/>.</summary>
        public PlaybackState State => _status.State;

        /// <summary>Why the component is not running (what is missing, or what failed and what to do); empty while running.</summary>
        public string FailureReason => _status.Reason;

        /// <summary>True while a transition plays or blends out.</summary>
        public bool IsPlaying => _player != null && _player.IsPlaying;

        /// <summary>The bones driven, the root bone (hips) first, parents before children (the order of pose arrays).</summary>
        public IReadOnlyList<Transform> Bones => _bones;

        /// <summary>
        /// The model's frame rate (its contract owns it); a request in model frames lasts frames / this seconds.
        /// NaN while no model is loaded: no other value is assumed here.
        /// </summary>
        public double ModelFrameRate => _player?.FrameRate ?? double.NaN;

        /// <summary>
        /// Transition to the pose <paramref name="clip"/> shows at <paramref name="clipTime"/>, arriving in
        /// <paramref name="seconds"/> (≤ 0: the settings' default). The pose is read from the clip through the
        /// component's playable graph in this frame's animation evaluation (the scene is never written to); the
        /// transition starts once it is read and still arrives <paramref name="seconds"/> after this call.
        /// </summary>
        /// <returns>The request's id, as <see cref="TransitionCompleted"/> reports it.</returns>
        /// <exception cref="InvalidOperationException">The component is not running (disabled, or its model failed to load) or no frame was shown yet.</exception>
        public int RequestTransition(AnimationClip clip, float clipTime, float seconds = 0)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            TransitionPlayer player = Running();
            using (s_Request.Auto())
            {
                // The clip's pose is read through the playable graph in this frame's animation evaluation (the
                // scene is never written); the request waits for it and arrives when asked, from the history
                // and the place where the character stands now.
                BeginRootMotionFrame();
                FlushShownPose();
                float length = seconds > 0 ? seconds : settings!.DefaultTransitionSeconds;
                WarnOutsideTrainedRange(player, length);
                int id = player.DeferTransition(length);
                _deferredFrame = RigCollector.WorldFrame(transform);
                _targetSampler!.Sample(clip, clipTime);
                return id;
            }
        }

        /// <summary>
        /// <see cref="RequestTransition(AnimationClip, float, float)"/> with the length in model frames
        /// (the model's rate, <see cref="ModelFrameRate"/>). Named apart from it on purpose: as an overload,
        /// <c>RequestTransition(clip, 0.2f, 1)</c> meant one frame (33 ms), not one second.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="modelFrames"/> below 1.</exception>
        public int RequestTransitionInFrames(AnimationClip clip, float clipTime, int modelFrames)
        {
            if (modelFrames < 1) throw new ArgumentOutOfRangeException(nameof(modelFrames), modelFrames, "expected at least one model frame");
            TransitionPlayer player = Running();
            return RequestTransition(clip, clipTime, (float)(modelFrames / player.FrameRate));
        }

        /// <summary>
        /// Transition to a pose: the root bone's local position and every bone's local rotation, in the order
        /// of <see cref="Bones"/>, arriving in <paramref name="seconds"/> (≤ 0: the settings' default). The root
        /// bone's position is relative to where the character stands now (with root motion on, a position
        /// 2 m ahead sends the character 2 m ahead).
        /// </summary>
        /// <exception cref="ArgumentException"><paramref name="localRotations"/> does not hold one rotation per bone.</exception>
        public int RequestTransition(Vector3 rootPosition, Quaternion[] localRotations, float seconds = 0)
        {
            TransitionPlayer player = Running();
            if (localRotations == null || localRotations.Length != _bones.Length) throw new ArgumentException($"expected {_bones.Length} rotations, one per bone of Bones", nameof(localRotations));
            _targetRoot[0] = rootPosition.x;
            _targetRoot[1] = rootPosition.y;
            _targetRoot[2] = rootPosition.z;
            for (int b = 0; b < localRotations.Length; b++) Write(localRotations[b], _targetRotations, b);
            return Request(player, seconds);
        }

        /// <summary>Ends the current transition at once (the controller's pose shows from the next frame).</summary>
        public void Cancel() => _player?.Cancel();

        private int RootBone { get; set; }

        private void OnEnable()
        {
            _isEnabled = true;
            Rebuild();
        }

        private void OnDisable()
        {
            _isEnabled = false;
            Listen(null);
            TearDown();
            // A failure keeps its reason (the component was disabled because of it); otherwise it waits to be enabled.
            if (_status.State != PlaybackState.Failed) _status.Wait("the component is disabled; enable it");
        }

        // The inspector changed a field of the component (e.g. another settings asset) in play mode: re-initialise
        // at the next frame (OnValidate may come during deserialization, where building a graph is not allowed).
        private void OnValidate() => _settingsChanged = true;

        // The settings asset was edited (its OnValidate).
        private void OnSettingsChanged(InbetweenerSettings changed) => _settingsChanged = true;

        private void Listen(InbetweenerSettings? s)
        {
            if (_listening == s) return;
            if (_listening != null) _listening.Changed -= OnSettingsChanged;
            _listening = s;
            if (_listening != null) _listening.Changed += OnSettingsChanged;
        }

        // Builds from the current settings; without settings it waits (no error: they may be assigned later).
        private void Rebuild()
        {
            TearDown();
            _settingsChanged = false;
            Listen(settings);
            if (settings == null)
            {
                _status.Wait("no settings asset is assigned; create one (Assets > Create > Δ-Interpolator > In-betweener Settings) and assign it to Settings");
                return;
            }

            try
            {
                Build();
                _status.Run();
            }
            catch (Exception e) when (e is DataFormatException || e is ArgumentException || e is InvalidOperationException || e is JointMapException)
            {
                Stop(e.Message, e);
            }
        }

        // Applies edited settings: blend times at once; a change of what the build used re-initialises.
        private void ApplySettingsChange()
        {
            _settingsChanged = false;
            if (settings != _listening || settings == null || _built == null || !_built.Matches(settings))
            {
                Rebuild();
                return;
            }

            if (_playback != null)
            {
                _playback.BlendInSeconds = settings.BlendInSeconds;
                _playback.BlendOutSeconds = settings.BlendOutSeconds;
                _playback.LockFeet = settings.LockFeet;
            }
        }

        // One error in the Console, and the component disabled (enable it again to retry).
        private void Stop(string reason, Exception? error)
        {
            _status.Fail(reason, error);
            Debug.LogError($"{name}: Motion Inbetweener disabled: {reason}", this);
            TearDown();
            enabled = false;
        }

        // Profiler markers (Window → Analysis → Profiler, CPU timeline) around the component's per-frame stages:
        // recording the pose shown last frame into the history, advancing the transition (which decodes
        // frames, and runs the network when a request's chunk is due on the main thread), and sampling a
        // request's target pose. Inference itself is marked by each backend (e.g. DeltaInterpolator.Sentis.Run).
        private static readonly ProfilerMarker s_RecordHistory = new ProfilerMarker("MotionInbetweener.RecordHistory");
        private static readonly ProfilerMarker s_Advance = new ProfilerMarker("MotionInbetweener.Advance");
        private static readonly ProfilerMarker s_Request = new ProfilerMarker("MotionInbetweener.RequestTransition");

        // The transition advances where the Animator does: rendered frames (Normal, UnscaledTime) or physics
        // steps (Fixed), by the step of its clock (Core's AnimationClock decides; only Unity's values are read here).
        private void Update()
        {
            if (_settingsChanged) ApplySettingsChange();
            if (_status.State == PlaybackState.Waiting && settings != null) Rebuild();
            Tick(FrameCallback.Update);
        }

        private void FixedUpdate() => Tick(FrameCallback.FixedUpdate);

        private void Tick(FrameCallback callback)
        {
            if (_player == null || _rootMotion == null || _animator == null) return;
            _clock.Mode = (AnimationClockMode)(int)_animator.updateMode;
            if (!_clock.Advance(callback, Time.deltaTime, Time.unscaledDeltaTime, Time.fixedDeltaTime)) return;
            // Where the character stands now is where the last frame was shown (the Animator applied its root motion since).
            BeginRootMotionFrame();
            using (s_RecordHistory.Auto()) FlushShownPose();
            StartSampledTarget();
            double time = _clock.Time;
            bool played;
            using (s_Advance.Auto()) played = _status.TryBeginFrame(_player, time, _modelName, _engineName);
            if (!played)
            {
                if (_status.State == PlaybackState.Failed)
                {
                    // The shared model is broken: the next character to enable loads it afresh.
                    if (_decoder != null) SharedDecoders.Discard(_decoder);
                    Stop(_status.Reason, _status.Error);
                }

                return;
            }

            Span<double> pose = _pose.AsSpan();
            _player.PoseRoot.CopyTo(pose.Slice(0, 3));
            _player.PoseRotations.CopyTo(pose.Slice(3));
            var controller = new Vector3D(_rootVelocity[3], _rootVelocity[4], _rootVelocity[5]);
            _rootMotion.Plan(_player, time, _clock.LastStep, controller, pose.Slice(0, 3), pose.Slice(3, 4));
            Vector3D velocity = _rootMotion.TransitionVelocity;
            _rootVelocity[0] = velocity.X;
            _rootVelocity[1] = velocity.Y;
            _rootVelocity[2] = velocity.Z;
            _rootVelocity[6] = _rootMotion.Enabled ? 1 : 0;
            _weight[0] = _player.Weight;
            _shownTime = time;
            _shownPending = true;
        }

        private void Build()
        {
            InbetweenerSettings s = settings != null ? settings : throw new InvalidOperationException("no settings asset is assigned; create one (Assets > Create > Δ-Interpolator > In-betweener Settings) and assign it");
            InbetweeningModel model = s.Model != null ? s.Model : throw new InvalidOperationException($"the settings {s.name} have no model; assign an imported in-betweening model");
            IInferenceBackendFactory factory = InferenceBackends.Find(s.Backend)
                ?? throw new InvalidOperationException($"the inference engine '{s.Backend}' is not installed; install its package (Sentis: com.unity.ai.inference 2.4.0 or later) or choose another in {s.name}");
            _animator = GetComponent<Animator>();
            _modelName = model.name;
            _engineName = factory.Name;
            _decoder = SharedDecoders.Acquire(model, factory);
            ModelContract contract = _decoder.Contract;
            CharacterRig rig = RigCollector.Collect(_animator, s, contract.Skeleton, out Core.Retargeting.JointMap jointMap, out _bones);
            SkeletonPoseConverter map = rig.CreatePoseConverter(contract.Skeleton, jointMap);
            RootBone = 0;
            _rootMotion = new RootMotion(rig.Armature) { Enabled = _animator.applyRootMotion };
            // The player reads these at each request and frame, so edited blend times apply without a rebuild.
            _playback = new PlaybackSettings { BlendInSeconds = s.BlendInSeconds, BlendOutSeconds = s.BlendOutSeconds, PastFrames = s.PastFrames, LockFeet = s.LockFeet };
            _player = new TransitionPlayer(map, _decoder, _playback);
            _built = SettingsSnapshot.Take(s);
            _player.TransitionCompleted += OnCompleted;
            int n = _bones.Length;
            _targetRotations = new double[4 * n];
            _recordRotations = new double[4 * n];
            _handles = new NativeArray<TransformStreamHandle>(n, Allocator.Persistent);
            for (int b = 0; b < n; b++) _handles[b] = _animator.BindStreamTransform(_bones[b]);
            _pose = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            _shown = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            _weight = new NativeArray<double>(1, Allocator.Persistent);
            _rootVelocity = new NativeArray<double>(7, Allocator.Persistent);
            // Until the job has run once (it does not while the Animator is culled), the pose shown is the
            // bones' current one, never zeros.
            ReadBones(_targetRoot, _targetRotations);
            Span<double> shown = _shown.AsSpan();
            new ReadOnlySpan<double>(_targetRoot).CopyTo(shown.Slice(0, 3));
            new ReadOnlySpan<double>(_targetRotations).CopyTo(shown.Slice(3));
            var job = new TransitionLayerJob { Bones = _handles, Pose = _pose, Shown = _shown, Weight = _weight, RootVelocity = _rootVelocity, RootBone = RootBone };
            _graph = PlayableGraph.Create(name + " (Δ-Interpolator)");
            _graph.SetTimeUpdateMode(DirectorUpdateMode.GameTime);
            AnimationPlayableOutput output = AnimationPlayableOutput.Create(_graph, "Δ-Interpolator", _animator);
            AnimationScriptPlayable playable = AnimationScriptPlayable.Create(_graph, job);
            output.SetSourcePlayable(playable);
            // Read what the Animator Controller produced (the outputs before this one), then blend over it.
            output.SetAnimationStreamSource(AnimationStreamSource.PreviousInputs);
            output.SetSortingOrder(LayerSortingOrder);
            // Clip targets are read by a pass-through layer just before this one.
            _targetSampler = new ClipTargetSampler(_graph, _animator, _handles, RootBone, (ushort)(LayerSortingOrder - 1));
            _graph.Play();
            // The bones' pose now is the first frame shown, so a request may follow at once (e.g. right after AddComponent).
            _shownTime = _clock.Time;
            _shownPending = true;
        }

        private void TearDown()
        {
            if (_graph.IsValid()) _graph.Destroy();
            _targetSampler?.Dispose();
            _targetSampler = null;
            if (_handles.IsCreated) _handles.Dispose();
            if (_pose.IsCreated) _pose.Dispose();
            if (_shown.IsCreated) _shown.Dispose();
            if (_weight.IsCreated) _weight.Dispose();
            if (_rootVelocity.IsCreated) _rootVelocity.Dispose();
            _rootMotion = null;
            if (_player != null) _player.TransitionCompleted -= OnCompleted;
            _player = null;
            if (_decoder != null) SharedDecoders.Release(_decoder);
            _decoder = null;
            _playback = null;
            _built = null;
        }

        private int Request(TransitionPlayer player, float seconds)
        {
            using (s_Request.Auto())
            {
                // The pose shown last frame must be in the history before the request reads it, and the target
                // goes into the same root-motion space, from where the character stands now.
                BeginRootMotionFrame();
                FlushShownPose();
                _rootMotion!.TargetToMotionSpace(_targetRoot, new Span<double>(_targetRotations, 0, 4));
                float length = seconds > 0 ? seconds : settings!.DefaultTransitionSeconds;
                WarnOutsideTrainedRange(player, length);
                return player.RequestTransition(_targetRoot, _targetRotations, length);
            }
        }

        // A request outside the ranges the model was trained on runs, with one Console warning per distinct
        // length (requests repeat every frame in some games: one warning is enough).
        private readonly HashSet<int> _warnedLengths = new HashSet<int>();

        private void WarnOutsideTrainedRange(TransitionPlayer player, float seconds)
        {
            int key = (int)Math.Round(seconds * player.FrameRate);
            if (_warnedLengths.Contains(key)) return;
            foreach (ModelCheck check in player.CheckRequest(seconds))
            {
                if (check.Severity != CheckSeverity.Warning) continue;
                _warnedLengths.Add(key);
                Debug.LogWarning($"{name}: {check.Message}; {check.Remedy}", this);
            }
        }

        private void FlushShownPose()
        {
            if (!_shownPending || _player == null || _rootMotion == null) return;
            _shownPending = false;
            ReadOnlySpan<double> shown = _shown.AsReadOnlySpan();
            shown.Slice(0, 3).CopyTo(_recordRoot);
            shown.Slice(3).CopyTo(_recordRotations);
            _rootMotion.ShownToMotionSpace(_recordRoot, new Span<double>(_recordRotations, 0, 4));
            _player.Record(_shownTime, _recordRoot, _recordRotations);
        }

        // A clip target requested earlier, once the animation evaluation has read it: placed where the
        // character stood when it was requested.
        private void StartSampledTarget()
        {
            if (!_player!.HasDeferredTransition || !_targetSampler!.TryRead(_targetRoot, _targetRotations)) return;
            _rootMotion!.TargetToMotionSpace(_deferredFrame, _targetRoot, new Span<double>(_targetRotations, 0, 4));
            _player.CompleteDeferredTransition(_targetRoot, _targetRotations);
        }

        private void BeginRootMotionFrame()
        {
            _rootMotion!.Enabled = _animator!.applyRootMotion;
            _rootMotion.BeginFrame(RigCollector.WorldFrame(transform));
        }

        private TransitionPlayer Running()
        {
            // Settings assigned through serialization or edited this frame: initialise now rather than at the next Update.
            if (_isEnabled && _settingsChanged) ApplySettingsChange();
            if (_isEnabled && _status.State == PlaybackState.Waiting && settings != null) Rebuild();
            if (_player == null)
            {
                throw new InvalidOperationException($"{name}: the Motion Inbetweener is not running: {_status.Reason}");
            }

            return _player;
        }

        private void ReadBones(double[] root, double[] rotations)
        {
            Vector3 p = _bones[RootBone].localPosition;
            root[0] = p.x;
            root[1] = p.y;
            root[2] = p.z;
            for (int b = 0; b < _bones.Length; b++) Write(_bones[b].localRotation, rotations, b);
        }

        private static void Write(Quaternion q, double[] rotations, int bone)
        {
            rotations[4 * bone] = q.w;
            rotations[4 * bone + 1] = q.x;
            rotations[4 * bone + 2] = q.y;
            rotations[4 * bone + 3] = q.z;
        }

        private void OnCompleted(TransitionCompletion completion) => TransitionCompleted?.Invoke(completion);
    }
}
