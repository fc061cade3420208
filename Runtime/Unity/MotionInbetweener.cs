using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using Unity.Profiling;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using UnityEngine;
using UnityEngine.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity
{
    /// <summary>Neural transitions for a character. Hand over to an Animator state with <see cref="RequestTransition(string, int, float, float)"/>: the character moves
    /// from the pose it shows now to the state's pose through frames the in-betweening model fills, and on arrival the controller is put in that state and plays on.
    /// Or, with no code, let the settings' <see cref="InbetweenerSettings.NeuralTransitions"/> replace the controller's own crossfades by in-betweens. A clip or pose
    /// request (<see cref="RequestTransition(AnimationClip, float, float)"/>) visits its pose, then the controller's own animation takes back over. Plays as an
    /// animation job layered after the Animator Controller, so it composes with whatever the controller does.</summary>
    /// <remarks>
    /// Thin glue over Core's <see cref="TransitionCharacter"/>: each frame <c>Update</c> gathers what Unity read (the binder, and the
    /// <see cref="AnimatorTransitionWatcher"/> for the controller's layers), makes one call, and the binder carries out its output: the
    /// pose into the job, which blends it over the controller's output, a state to sample, a state to play. Requests from game code go through <see cref="CharacterRequests"/>.
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
    public sealed class MotionInbetweener : MonoBehaviour, IAnimationWindowPreview
    {
        [SerializeField]
        [Tooltip("Model, inference engine, joint names and blend times.")]
        private InbetweenerSettings? settings = null;

        private Animator? _animator;
        private CharacterBuild? _build;
        private TransitionCharacter? _character;
        private TransitionLayerBinder? _binder;
        private Transform[] _bones = new Transform[0];
        private readonly PlaybackStatus _status = new PlaybackStatus();
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
        /// default); then the controller's own animation takes back over (blend-out): to end in a state and play on, hand off with
        /// <see cref="RequestTransition(string, int, float, float)"/>. The pose is read from the clip through the component's playable graph in this frame's
        /// animation evaluation (the scene is never written to); the transition starts once it is read and still arrives <paramref name="seconds"/>after this call.</summary>
        /// <returns>The request's id, as <see cref="TransitionCompleted"/> reports it.</returns>
        /// <exception cref="ArgumentNullException"><paramref name="clip"/> is null.</exception>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="clipTime"/> negative or not finite; <paramref name="seconds"/> NaN or longer than the model spans.</exception>
        /// <exception cref="InvalidOperationException">The component is not running (disabled, or its model failed to load).</exception>
        public int RequestTransition(AnimationClip clip, float clipTime, float seconds = 0) => CharacterRequests.RequestClip(this, clip, clipTime, seconds);

        /// <summary><see cref="RequestTransition(AnimationClip, float, float)"/>with the length in model frames (the model's rate, <see cref="ModelFrameRate"/>). Named
        /// apart from it on purpose: as an overload, <c>RequestTransition(clip, 0.2f, 1)</c>meant one frame (33 ms), not one second.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="modelFrames"/> below 1.</exception>
        public int RequestTransitionInFrames(AnimationClip clip, float clipTime, int modelFrames) => CharacterRequests.RequestClipInFrames(this, clip, clipTime, modelFrames);

        /// <summary>Transition to a pose: the root bone's local position and every bone's local rotation, in the order of <see cref="Bones"/>, arriving in <paramref
        /// name="seconds"/>(≤ 0: the settings' default); then the controller takes back over (blend-out). The root bone's position is relative to where the character
        /// stands now (with root motion on, a position 2 m ahead sends the character 2 m ahead).</summary>
        /// <exception cref="ArgumentException"><paramref name="localRotations"/> is null or does not hold one rotation per bone; <paramref name="seconds"/> NaN.</exception>
        public int RequestTransition(Vector3 rootPosition, Quaternion[] localRotations, float seconds = 0) => CharacterRequests.RequestPose(this, rootPosition, localRotations, seconds);

        /// <summary>Hand over to an Animator state: transition to the pose state <paramref name="stateName"/>(its name, or full path such as
        /// <c>"Base Layer.Roll"</c>) of <paramref name="layer"/>shows <paramref name="timeInState"/>seconds in, arriving in <paramref name="seconds"/>(≤ 0: the
        /// settings' default); in the frame it arrives the controller is put in that state at that time (<c>Animator.PlayInFixedTime</c>) and the layer lets go,
        /// so the state plays on with no blend back. The target is read off-scene from a copy of the controller with the character's parameters now (a 1D/2D
        /// blend tree blends as it would on the character).</summary>
        /// <exception cref="ArgumentNullException"><paramref name="stateName"/> is null.</exception>
        /// <exception cref="ArgumentException">The controller has no such state on <paramref name="layer"/>.</exception>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="layer"/> is not a layer of the controller, <paramref name="timeInState"/> negative or not
        /// finite, <paramref name="seconds"/> NaN or longer than the model spans.</exception>
        /// <exception cref="InvalidOperationException">The component is not running, or the Animator has no controller.</exception>
        public int RequestTransition(string stateName, int layer, float timeInState, float seconds = 0) =>
            CharacterRequests.RequestState(this, StateHash(stateName), nameof(stateName), layer, timeInState, seconds);

        /// <summary><see cref="RequestTransition(string, int, float, float)"/>with the state's hash (<c>Animator.StringToHash</c> of its name or full path).</summary>
        public int RequestTransition(int stateHash, int layer, float timeInState, float seconds = 0) => CharacterRequests.RequestState(this, stateHash, nameof(stateHash), layer, timeInState, seconds);

        /// <summary><see cref="RequestTransition(string, int, float, float)"/>with the length in model frames (<see cref="ModelFrameRate"/>).</summary>
        public int RequestTransitionInFrames(string stateName, int layer, float timeInState, int modelFrames) =>
            CharacterRequests.RequestStateInFrames(this, StateHash(stateName), nameof(stateName), layer, timeInState, modelFrames);

        /// <summary><see cref="RequestTransition(int, int, float, float)"/>with the length in model frames (<see cref="ModelFrameRate"/>).</summary>
        public int RequestTransitionInFrames(int stateHash, int layer, float timeInState, int modelFrames) =>
            CharacterRequests.RequestStateInFrames(this, stateHash, nameof(stateHash), layer, timeInState, modelFrames);

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
        // shown last frame, advancing the transition, planning root motion: one Core call); requests are marked by CharacterRequests. The
        // schedulers' stages are marked where they pump (SchedulerPump); inference by each backend (e.g. DeltaInterpolator.Sentis.Run).
        private static readonly ProfilerMarker s_Frame = new ProfilerMarker("MotionInbetweener.Frame");

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

        // Gather what Unity read, one call into Core's character, the binder carries out its output (pose, state to sample, state to play).
        private void Tick(FrameCallback callback)
        {
            if (_character == null || _binder == null || _animator == null) return;
            CharacterFrameInput input = _binder.Gather(callback);
            CharacterFrameOutput frame;
            using (s_Frame.Auto()) frame = _character.Frame(input, _binder.Shown, _binder.Sampled);
            if (!_binder.Apply(frame)) Failed(frame);
        }

        // The inference engine failed in this frame (once: the component stops).
        private void Failed(in CharacterFrameOutput frame)
        {
            // The shared model is broken: the next character to enable loads it afresh.
            if (_build != null) SharedSchedulers.Discard(_build.Scheduler);
            Stop(frame.FailureReason!, frame.Error);
        }

        private void Build()
        {
            InbetweenerSettings s = settings != null ? settings : throw new InvalidOperationException("no settings asset is assigned; create one (Assets > Create > Δ-Interpolator > In-betweener Settings) and assign it");
            _animator = GetComponent<Animator>();
            _build = CharacterBuild.Create(_animator, s, this, name + " (Δ-Interpolator)", LayerSortingOrder);
            _character = _build.Character;
            _binder = _build.Binder;
            _bones = _build.Bones;
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

        /// <summary>The running component's requests; initialises first when settings arrived since the last frame.</summary>
        /// <exception cref="InvalidOperationException">The component is not running (disabled, or its model failed to load).</exception>
        internal CharacterRequests Running()
        {
            // Settings assigned through serialization or edited this frame: initialise now rather than at the next Update.
            if (_isEnabled && _settingsChanged) ApplySettingsChange();
            if (_isEnabled && _status.ShouldStart(settings != null)) Rebuild();
            return _build?.Requests ?? throw new InvalidOperationException($"{name}: the Motion Inbetweener is not running: {_status.Reason}");
        }

        private static int StateHash(string stateName) => Animator.StringToHash(stateName ?? throw new ArgumentNullException(nameof(stateName)));

        /// <summary>A <see cref="NeuralTransition"/> behaviour's choice for a state, recorded when the Animator enters the state.</summary>
        internal void MarkState(int stateHash, int layer, NeuralTransitionMode mode) => _build?.Watcher.MarkState(stateHash, layer, mode);

        private void OnCompleted(TransitionCompletion completion) => TransitionCompleted?.Invoke(completion);

        // The Animation window's and Timeline's Editor previews: the key fill's result over the clip being keyed (FillPreviewLayer). Not game frames.
        private FillPreviewLayer? _fillPreview;
        private FillPreviewLayer FillPreview => _fillPreview ??= new FillPreviewLayer(gameObject);
        void IAnimationWindowPreview.StartPreview() => FillPreview.Start();
        void IAnimationWindowPreview.StopPreview() => FillPreview.Stop();
        void IAnimationWindowPreview.UpdatePreviewGraph(PlayableGraph graph) => FillPreview.Update(graph);
        Playable IAnimationWindowPreview.BuildPreviewGraph(PlayableGraph graph, Playable inputPlayable) => FillPreview.Build(graph, inputPlayable, enabled);
    }
}
