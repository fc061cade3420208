using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Inference;
using Unity.Profiling;
using DeltaInterpolator.Core.Playback;
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
    /// Bones are found by the model's joint names under the Animator (<see cref="InbetweenerSettings.Joints"/>
    /// renames them); the character must share the model's skeleton and rest pose. The root joint's
    /// position is its local position under its parent, so transitions happen in the character's space.
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
        private Quaternion[] _savedRotations = new Quaternion[0];
        private double _shownTime;
        private bool _shownPending;

        /// <summary>Reports each request once: when the character shows its target, or when a newer request or <see cref="Cancel"/> ends it first.</summary>
        public event Action<TransitionCompletion>? TransitionCompleted;

        /// <summary>The settings asset (assign before the component is enabled).</summary>
        public InbetweenerSettings? Settings
        {
            get => settings;
            set => settings = value;
        }

        /// <summary>True while a transition plays or blends out.</summary>
        public bool IsPlaying => _player != null && _player.IsPlaying;

        /// <summary>The bones driven, in the model's joint order (the order of pose arrays).</summary>
        public IReadOnlyList<Transform> Bones => _bones;

        /// <summary>The model's frame rate; a request in model frames lasts frames / this seconds.</summary>
        public double ModelFrameRate => _player?.FrameRate ?? 30;

        /// <summary>
        /// Transition to the pose <paramref name="clip"/> shows at <paramref name="clipTime"/>, arriving in
        /// <paramref name="seconds"/> (≤ 0: the settings' default).
        /// </summary>
        /// <returns>The request's id, as <see cref="TransitionCompleted"/> reports it.</returns>
        /// <exception cref="InvalidOperationException">The component is not running (disabled, or its model failed to load) or no frame was shown yet.</exception>
        public int RequestTransition(AnimationClip clip, float clipTime, float seconds = 0)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            TransitionPlayer player = Running();
            // Sample the clip onto the bones, read the pose, and put the bones back: the Animator
            // overwrites them in its next evaluation anyway, but scripts reading them this frame must not see it.
            int n = _bones.Length;
            Vector3 savedRoot = _bones[RootBone].localPosition;
            for (int b = 0; b < n; b++) _savedRotations[b] = _bones[b].localRotation;
            clip.SampleAnimation(gameObject, clipTime);
            ReadBones(_targetRoot, _targetRotations);
            for (int b = 0; b < n; b++) _bones[b].localRotation = _savedRotations[b];
            _bones[RootBone].localPosition = savedRoot;
            return Request(player, seconds);
        }

        /// <summary>
        /// <see cref="RequestTransition(AnimationClip, float, float)"/> with the length in model frames
        /// (the model's rate, <see cref="ModelFrameRate"/>).
        /// </summary>
        public int RequestTransition(AnimationClip clip, float clipTime, int modelFrames) => RequestTransition(clip, clipTime, (float)(modelFrames / ModelFrameRate));

        /// <summary>
        /// Transition to a pose: the root bone's local position and every bone's local rotation, in the order
        /// of <see cref="Bones"/>, arriving in <paramref name="seconds"/> (≤ 0: the settings' default).
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
            try
            {
                Build();
            }
            catch (Exception e) when (e is DataFormatException || e is ArgumentException || e is InvalidOperationException)
            {
                Debug.LogError($"{name}: Motion Inbetweener disabled: {e.Message}", this);
                TearDown();
                enabled = false;
            }
        }

        private void OnDisable() => TearDown();

        // Profiler markers (Window → Analysis → Profiler, CPU timeline) around the component's per-frame stages:
        // recording the pose shown last frame into the history, advancing the transition (which decodes
        // frames, and runs the network when a request's chunk is due on the main thread), and sampling a
        // request's target pose. Inference itself is marked by each backend (e.g. DeltaInterpolator.Sentis.Run).
        private static readonly ProfilerMarker s_RecordHistory = new ProfilerMarker("MotionInbetweener.RecordHistory");
        private static readonly ProfilerMarker s_Advance = new ProfilerMarker("MotionInbetweener.Advance");
        private static readonly ProfilerMarker s_Request = new ProfilerMarker("MotionInbetweener.RequestTransition");

        private void Update()
        {
            if (_player == null) return;
            using (s_RecordHistory.Auto()) FlushShownPose();
            using (s_Advance.Auto()) _player.BeginFrame(Time.timeAsDouble);
            Span<double> pose = _pose.AsSpan();
            _player.PoseRoot.CopyTo(pose.Slice(0, 3));
            _player.PoseRotations.CopyTo(pose.Slice(3));
            _weight[0] = _player.Weight;
            _shownTime = Time.timeAsDouble;
            _shownPending = true;
        }

        private void Build()
        {
            InbetweenerSettings s = settings != null ? settings : throw new InvalidOperationException("no settings asset is assigned; create one (Assets > Create > Δ-Interpolator > In-betweener Settings) and assign it");
            InbetweeningModel model = s.Model != null ? s.Model : throw new InvalidOperationException($"the settings {s.name} have no model; assign an imported in-betweening model");
            IInferenceBackendFactory factory = InferenceBackends.Find(s.Backend)
                ?? throw new InvalidOperationException($"the inference engine '{s.Backend}' is not installed; install its package (Sentis: com.unity.ai.inference 2.4.0 or later) or choose another in {s.name}");
            _animator = GetComponent<Animator>();
            _decoder = SharedDecoders.Acquire(model, factory);
            ModelContract contract = _decoder.Contract;
            _bones = FindBones(contract, s.Joints);
            var map = new NameJointMap(contract.Skeleton, contract.UnitScale, contract.Skeleton.Names);
            RootBone = map.RootBone;
            var playback = new PlaybackSettings { BlendInSeconds = s.BlendInSeconds, BlendOutSeconds = s.BlendOutSeconds, PastFrames = s.PastFrames };
            _player = new TransitionPlayer(map, _decoder, playback);
            _player.TransitionCompleted += OnCompleted;
            int n = _bones.Length;
            _targetRotations = new double[4 * n];
            _savedRotations = new Quaternion[n];
            _handles = new NativeArray<TransformStreamHandle>(n, Allocator.Persistent);
            for (int b = 0; b < n; b++) _handles[b] = _animator.BindStreamTransform(_bones[b]);
            _pose = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            _shown = new NativeArray<double>(3 + 4 * n, Allocator.Persistent);
            _weight = new NativeArray<double>(1, Allocator.Persistent);
            // Until the job has run once (it does not while the Animator is culled), the pose shown is the
            // bones' current one, never zeros.
            ReadBones(_targetRoot, _targetRotations);
            Span<double> shown = _shown.AsSpan();
            new ReadOnlySpan<double>(_targetRoot).CopyTo(shown.Slice(0, 3));
            new ReadOnlySpan<double>(_targetRotations).CopyTo(shown.Slice(3));
            var job = new TransitionLayerJob { Bones = _handles, Pose = _pose, Shown = _shown, Weight = _weight, RootBone = RootBone };
            _graph = PlayableGraph.Create(name + " (Δ-Interpolator)");
            _graph.SetTimeUpdateMode(DirectorUpdateMode.GameTime);
            AnimationPlayableOutput output = AnimationPlayableOutput.Create(_graph, "Δ-Interpolator", _animator);
            AnimationScriptPlayable playable = AnimationScriptPlayable.Create(_graph, job);
            output.SetSourcePlayable(playable);
            // Read what the Animator Controller produced (the outputs before this one), then blend over it.
            output.SetAnimationStreamSource(AnimationStreamSource.PreviousInputs);
            _graph.Play();
            _shownPending = false;
        }

        private void TearDown()
        {
            if (_graph.IsValid()) _graph.Destroy();
            if (_handles.IsCreated) _handles.Dispose();
            if (_pose.IsCreated) _pose.Dispose();
            if (_shown.IsCreated) _shown.Dispose();
            if (_weight.IsCreated) _weight.Dispose();
            if (_player != null) _player.TransitionCompleted -= OnCompleted;
            _player = null;
            if (_decoder != null) SharedDecoders.Release(_decoder);
            _decoder = null;
        }

        private Transform[] FindBones(ModelContract contract, JointBinding[] renames)
        {
            var boneOf = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (JointBinding r in renames)
            {
                if (!string.IsNullOrEmpty(r.joint) && !string.IsNullOrEmpty(r.bone)) boneOf[r.joint] = r.bone;
            }

            IReadOnlyList<string> joints = contract.Skeleton.Names;
            var bones = new Transform[joints.Count];
            var missing = new List<string>();
            for (int j = 0; j < joints.Count; j++)
            {
                string bone = boneOf.TryGetValue(joints[j], out string? renamed) ? renamed : joints[j];
                Transform? found = FindDescendant(transform, bone);
                if (found == null) missing.Add(bone);
                else bones[j] = found;
            }

            if (missing.Count > 0)
            {
                throw new InvalidOperationException($"no bone called {string.Join(", ", missing)} under {name}; add joint bindings for them in the settings (model joint → bone name)");
            }

            return bones;
        }

        private static Transform? FindDescendant(Transform parent, string boneName)
        {
            for (int c = 0; c < parent.childCount; c++)
            {
                Transform child = parent.GetChild(c);
                if (child.name == boneName) return child;
                Transform? below = FindDescendant(child, boneName);
                if (below != null) return below;
            }

            return null;
        }

        private int Request(TransitionPlayer player, float seconds)
        {
            using (s_Request.Auto())
            {
                // The pose shown last frame must be in the history before the request reads it.
                FlushShownPose();
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
            if (!_shownPending || _player == null) return;
            _shownPending = false;
            ReadOnlySpan<double> shown = _shown.AsReadOnlySpan();
            _player.Record(_shownTime, shown.Slice(0, 3), shown.Slice(3));
        }

        private TransitionPlayer Running()
        {
            if (_player == null) throw new InvalidOperationException($"{name}: the Motion Inbetweener is not running (disabled, or its model failed to load: see the Console)");
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
