using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using Unity.Profiling;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>Neural transitions for a character: call <see cref="RequestTransition(AnimationClip, float, float)"/>(or with a pose) and the character moves from the
    /// pose it shows now to the target through frames that the in-betweening model fills, arriving on the first rendered frame at or after the requested time; then its
    /// own animation takes back over. Plays as an animation job layered after the Animator Controller, so it composes with whatever the controller does.</summary>
    /// <remarks>
    /// Thin glue over Core's <see cref="TransitionCharacter"/>: each frame <c>Update</c> gathers what Unity read, makes
    /// one call, and the binder writes its output into the job, which blends it over the controller's output.
    /// The network runs on a worker thread when the engine allows it, otherwise on the main thread, pumped once per
    /// frame before every script's <c>Update</c> (<see cref="SchedulerPump"/>).
    /// The settings choose the rig (<see cref="InbetweenerSettings.Rig"/>): a humanoid avatar's bones and
    /// T-pose, or a generic rig's bones by a joint map and a reference pose; Core's <see cref="CharacterRig"/>
    /// maps them onto the model's skeleton (handedness, units, bone axes, joints the rig lacks) and refuses,
    /// at start, bones it cannot map or a reference pose that is not a T-pose. Bones the model does not know
    /// (fingers, twist bones) keep the character's own animation. With <c>Animator.applyRootMotion</c> on, a
    /// transition moves the character through the root motion (the stream's velocity) along the model's
    /// root trajectory (Core's <see cref="RootMotion"/>); off, it moves the root bone inside the character.
    /// <para>Transitions run on the Animator's clock (<c>Animator.updateMode</c>, Core's <see cref="AnimationClock"/>).
    /// Settings may arrive late, and edits in play mode apply (blend times at once, the rest by re-initialising).
    /// When the engine fails while playing, one error names the model and what to do, and the component disables itself.</para>
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
        private CharacterBuild? _build;
        private TransitionCharacter? _character;
        private TransitionLayerBinder? _binder;
        private Transform[] _bones = new Transform[0];
        private double[] _targetRoot = new double[3];
        private double[] _targetRotations = new double[0];
        private readonly PlaybackStatus _status = new PlaybackStatus();
        private readonly TrainedRangeWarnings _warnings = new TrainedRangeWarnings();
        private InbetweenerSettings? _listening;
        private bool _isEnabled;
        private bool _settingsChanged;

        /// <summary>The sorting order of the component's animation output: after the Animator Controller (whose output sorts at 0) and before IK and constraint layers
        /// such as Animation Rigging's (its RigBuilder sorts at 1000), so rigs constrain the transition's pose rather than being overwritten by it.</summary>
        public const ushort LayerSortingOrder = 500;

        /// <summary>Reports each request once: when the character shows its target, or when a newer request or <see cref="Cancel"/> ends it first.</summary>
        public event Action<TransitionCompletion>? TransitionCompleted;

        /// <summary>The settings asset. May be assigned at any time (e.g. after <c>AddComponent</c>): an enabled component initialises from it at once; a different asset
        /// re-initialises it.</summary>
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
        public bool IsPlaying => _character != null && _character.Player.IsPlaying;

        /// <summary>The bones driven, the root bone (hips) first, parents before children (the order of pose arrays).</summary>
        public IReadOnlyList<Transform> Bones => _bones;

        /// <summary>The model's frame rate (its contract owns it); a request in model frames lasts frames / this seconds. NaN while no model is loaded: no other value is
        /// assumed here.</summary>
        public double ModelFrameRate => _character?.Player.FrameRate ?? double.NaN;

        /// <summary>Transition to the pose <paramref name="clip"/>shows at <paramref name="clipTime"/>, arriving in <paramref name="seconds"/>(≤ 0: the settings'
        /// default). The pose is read from the clip through the component's playable graph in this frame's animation evaluation (the scene is never written to); the
        /// transition starts once it is read and still arrives <paramref name="seconds"/>after this call.</summary>
        /// <returns>The request's id, as <see cref="TransitionCompleted"/> reports it.</returns>
        /// <exception cref="InvalidOperationException">The component is not running (disabled, or its model failed to load) or no frame was shown yet.</exception>
        public int RequestTransition(AnimationClip clip, float clipTime, float seconds = 0)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            TransitionCharacter character = Running();
            using (s_Request.Auto())
            {
                Showed(character);
                float length = seconds > 0 ? seconds : settings!.DefaultTransitionSeconds;
                _warnings.Warn(character.Player, length, this);
                int id = character.DeferTransition(length);
                _binder!.Sampler.Sample(clip, clipTime);
                return id;
            }
        }

        /// <summary><see cref="RequestTransition(AnimationClip, float, float)"/>with the length in model frames (the model's rate, <see cref="ModelFrameRate"/>). Named
        /// apart from it on purpose: as an overload, <c>RequestTransition(clip, 0.2f, 1)</c>meant one frame (33 ms), not one second.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="modelFrames"/> below 1.</exception>
        public int RequestTransitionInFrames(AnimationClip clip, float clipTime, int modelFrames)
        {
            if (modelFrames < 1) throw new ArgumentOutOfRangeException(nameof(modelFrames), modelFrames, "expected at least one model frame");
            TransitionCharacter character = Running();
            return RequestTransition(clip, clipTime, (float)(modelFrames / character.Player.FrameRate));
        }

        /// <summary>Transition to a pose: the root bone's local position and every bone's local rotation, in the order of <see cref="Bones"/>, arriving in <paramref
        /// name="seconds"/>(≤ 0: the settings' default). The root bone's position is relative to where the character stands now (with root motion on, a position 2 m
        /// ahead sends the character 2 m ahead).</summary>
        /// <exception cref="ArgumentException"><paramref name="localRotations"/> does not hold one rotation per bone.</exception>
        public int RequestTransition(Vector3 rootPosition, Quaternion[] localRotations, float seconds = 0)
        {
            TransitionCharacter character = Running();
            if (localRotations == null || localRotations.Length != _bones.Length) throw new ArgumentException($"expected {_bones.Length} rotations, one per bone of Bones", nameof(localRotations));
            _targetRoot[0] = rootPosition.x;
            _targetRoot[1] = rootPosition.y;
            _targetRoot[2] = rootPosition.z;
            for (int b = 0; b < localRotations.Length; b++) UnityPoses.Write(localRotations[b], _targetRotations, 4 * b);
            return Request(character, seconds);
        }

        /// <summary>Ends the current transition at once (the controller's pose shows from the next frame).</summary>
        public void Cancel() => _character?.Cancel();

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

            // Any exception of the load (Sentis asserts, `new Worker`, a backend factory's own type) stops the component once: no reload every frame.
            if (!_status.TryStart(Build, settings.Model != null ? settings.Model.name : settings.name)) Stop(_status.Reason, _status.Error);
        }

        // Applies edited settings: blend times at once; a change of what the build used re-initialises.
        private void ApplySettingsChange()
        {
            _settingsChanged = false;
            if (settings != _listening || settings == null || _build == null || !_build.Built.Matches(settings))
            {
                Rebuild();
                return;
            }

            // The character reads these at each request and frame.
            _build.Playback.BlendInSeconds = settings.BlendInSeconds;
            _build.Playback.BlendOutSeconds = settings.BlendOutSeconds;
            _build.Playback.LockFeet = settings.LockFeet;
        }

        // One error in the Console, and the component disabled (enable it again to retry).
        private void Stop(string reason, Exception? error)
        {
            _status.Fail(reason, error);
            Debug.LogError($"{name}: Motion Inbetweener disabled: {reason}", this);
            TearDown();
            enabled = false;
        }

        // Profiler markers (Window → Analysis → Profiler, CPU timeline) around the component's frame (recording the pose
        // shown last frame, advancing the transition, planning root motion: one Core call) and its requests. The
        // schedulers' stages are marked where they pump (SchedulerPump); inference by each backend (e.g. DeltaInterpolator.Sentis.Run).
        private static readonly ProfilerMarker s_Frame = new ProfilerMarker("MotionInbetweener.Frame");
        private static readonly ProfilerMarker s_Request = new ProfilerMarker("MotionInbetweener.RequestTransition");

        // The transition advances where the Animator does: rendered frames (Normal, UnscaledTime) or physics
        // steps (Fixed), by the step of its clock (Core's AnimationClock decides; only Unity's values are read here).
        private void Update()
        {
            if (_settingsChanged) ApplySettingsChange();
            if (_status.ShouldStart(settings != null)) Rebuild();
            SchedulerPump.CheckPumpedThisFrame(this);
            Tick(FrameCallback.Update);
        }

        private void FixedUpdate() => Tick(FrameCallback.FixedUpdate);

        // Gather what Unity read, one call into Core's character, write its output into the job.
        private void Tick(FrameCallback callback)
        {
            if (_character == null || _binder == null || _animator == null) return;
            CharacterFrameInput input = _binder.Gather(callback, _animator);
            CharacterFrameOutput frame;
            using (s_Frame.Auto()) frame = _character.Frame(input, _binder.Shown, _binder.Sampler.Read());
            if (frame.Played) _binder.Write(frame);
            if (!frame.Failed) return;
            // The shared model is broken: the next character to enable loads it afresh.
            if (_build != null) SharedSchedulers.Discard(_build.Scheduler);
            Stop(frame.FailureReason!, frame.Error);
        }

        private void Build()
        {
            InbetweenerSettings s = settings != null ? settings : throw new InvalidOperationException("no settings asset is assigned; create one (Assets > Create > Δ-Interpolator > In-betweener Settings) and assign it");
            _animator = GetComponent<Animator>();
            _build = CharacterBuild.Create(_animator, s, name + " (Δ-Interpolator)", LayerSortingOrder);
            _character = _build.Character;
            _binder = _build.Binder;
            _bones = _build.Bones;
            _targetRotations = new double[4 * _bones.Length];
            _character.Player.TransitionCompleted += OnCompleted;
        }

        private void TearDown()
        {
            if (_character != null) _character.Player.TransitionCompleted -= OnCompleted;
            _build?.Dispose();
            _build = null;
            _character = null;
            _binder = null;
        }

        private int Request(TransitionCharacter character, float seconds)
        {
            using (s_Request.Auto())
            {
                // The pose shown last frame must be in the history before the request reads it, and the target
                // goes into the same root-motion space, from where the character stands now.
                Showed(character);
                float length = seconds > 0 ? seconds : settings!.DefaultTransitionSeconds;
                _warnings.Warn(character.Player, length, this);
                return character.RequestTransition(_targetRoot, _targetRotations, length);
            }
        }

        // Where the character stands now and the pose the job showed last, before a request made between frames.
        private void Showed(TransitionCharacter character) => character.Showed(UnityPoses.Place(transform), _animator!.applyRootMotion, _binder!.Shown);

        private TransitionCharacter Running()
        {
            // Settings assigned through serialization or edited this frame: initialise now rather than at the next Update.
            if (_isEnabled && _settingsChanged) ApplySettingsChange();
            if (_isEnabled && _status.ShouldStart(settings != null)) Rebuild();
            if (_character == null)
            {
                throw new InvalidOperationException($"{name}: the Motion Inbetweener is not running: {_status.Reason}");
            }

            return _character;
        }

        private void OnCompleted(TransitionCompletion completion) => TransitionCompleted?.Invoke(completion);
    }
}
