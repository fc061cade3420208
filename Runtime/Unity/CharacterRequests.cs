using System;
using DeltaInterpolator.Core.Playback;
using Unity.Profiling;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// A <see cref="MotionInbetweener"/>'s requests from game code: a clip's pose, a pose, or a hand-off into an Animator
    /// state. The static entry points check what needs no running component (naming the argument) before they ask whether it runs,
    /// so a bad argument is refused the same way whatever the component's state; the running requests check what needs the
    /// controller, hand Core the pose shown and where the character stands, warn once per length the model was not trained on,
    /// and ask the binder to sample a target off-scene.
    /// </summary>
    internal sealed class CharacterRequests : IControllerStates
    {
        private readonly TransitionCharacter _character;
        private readonly TransitionLayerBinder _binder;
        private readonly Animator _animator;
        private readonly InbetweenerSettings _settings;
        private readonly MotionInbetweener _component;
        private readonly TrainedRangeWarnings _warnings = new TrainedRangeWarnings();
        private readonly double[] _targetRoot = new double[3];
        private readonly double[] _targetRotations;

        // The Profiler's marker around every request (Window → Analysis → Profiler, CPU timeline).
        private static readonly ProfilerMarker s_Request = new ProfilerMarker("MotionInbetweener.RequestTransition");

        public CharacterRequests(TransitionCharacter character, TransitionLayerBinder binder, Animator animator, InbetweenerSettings settings, MotionInbetweener component, int bones)
        {
            _character = character;
            _binder = binder;
            _animator = animator;
            _settings = settings;
            _component = component;
            _targetRotations = new double[4 * bones];
        }

        int IControllerStates.LayerCount => _animator.layerCount;

        bool IControllerStates.HasState(int layer, int stateHash) => _animator.HasState(layer, stateHash);

        /// <summary>A clip request: <paramref name="clip"/>, <paramref name="clipTime"/> and <paramref name="seconds"/> checked, then the running component asked.</summary>
        public static int RequestClip(MotionInbetweener component, AnimationClip clip, float clipTime, float seconds)
        {
            CheckClip(clip, clipTime);
            CheckSeconds(seconds);
            return component.Running().Clip(clip, clipTime, seconds);
        }

        /// <summary><see cref="RequestClip"/> with the length in model frames.</summary>
        public static int RequestClipInFrames(MotionInbetweener component, AnimationClip clip, float clipTime, int modelFrames)
        {
            CheckClip(clip, clipTime);
            CheckFrames(modelFrames);
            CharacterRequests running = component.Running();
            return running.Clip(clip, clipTime, running.FramesToSeconds(modelFrames));
        }

        /// <summary>A pose request: <paramref name="localRotations"/> and <paramref name="seconds"/> checked, then the running component asked.</summary>
        public static int RequestPose(MotionInbetweener component, Vector3 rootPosition, Quaternion[] localRotations, float seconds)
        {
            if (localRotations == null) throw new ArgumentNullException(nameof(localRotations), "expected one rotation per bone of Bones");
            CheckSeconds(seconds);
            return component.Running().Pose(rootPosition, localRotations, seconds);
        }

        /// <summary>A hand-off: <paramref name="layer"/>, <paramref name="timeInState"/> and <paramref name="seconds"/> checked, then the running component asked.</summary>
        public static int RequestState(MotionInbetweener component, int stateHash, string stateArgument, int layer, float timeInState, float seconds)
        {
            CheckState(layer, timeInState);
            CheckSeconds(seconds);
            return component.Running().State(stateHash, stateArgument, layer, timeInState, seconds);
        }

        /// <summary><see cref="RequestState"/> with the length in model frames.</summary>
        public static int RequestStateInFrames(MotionInbetweener component, int stateHash, string stateArgument, int layer, float timeInState, int modelFrames)
        {
            CheckState(layer, timeInState);
            CheckFrames(modelFrames);
            CharacterRequests running = component.Running();
            return running.State(stateHash, stateArgument, layer, timeInState, running.FramesToSeconds(modelFrames));
        }

        private static void CheckClip(AnimationClip clip, float clipTime)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (!(clipTime >= 0) || float.IsInfinity(clipTime)) throw new ArgumentOutOfRangeException(nameof(clipTime), clipTime, "expected a finite time in the clip, in seconds ≥ 0");
        }

        private static void CheckState(int layer, float timeInState)
        {
            if (layer < 0) throw new ArgumentOutOfRangeException(nameof(layer), layer, "expected a layer index of the Animator Controller, ≥ 0");
            if (!(timeInState >= 0) || float.IsInfinity(timeInState)) throw new ArgumentOutOfRangeException(nameof(timeInState), timeInState, "expected a finite time in the state, in seconds ≥ 0");
        }

        // NaN is refused rather than silently taken as "the default" (≤ 0 is the default on purpose).
        private static void CheckSeconds(float seconds)
        {
            if (float.IsNaN(seconds)) throw new ArgumentOutOfRangeException(nameof(seconds), seconds, "expected seconds > 0, or ≤ 0 for the settings' default length");
        }

        private static void CheckFrames(int modelFrames)
        {
            if (modelFrames < 1) throw new ArgumentOutOfRangeException(nameof(modelFrames), modelFrames, "expected at least one model frame");
        }

        /// <summary>Seconds of <paramref name="modelFrames"/> model frames (checked by the caller).</summary>
        public float FramesToSeconds(int modelFrames) => (float)(modelFrames / _character.Player.FrameRate);

        /// <summary>The pose <paramref name="clip"/> shows at <paramref name="clipTime"/>, read off-scene in this frame's evaluation.</summary>
        private int Clip(AnimationClip clip, float clipTime, float seconds)
        {
            using (s_Request.Auto())
            {
                float length = Length(seconds);
                Showed();
                int id = _character.DeferTransition(length);
                _binder.SampleClip(clip, clipTime);
                return id;
            }
        }

        /// <summary>A pose given by the caller: the root bone's local position and one local rotation per bone.</summary>
        private int Pose(Vector3 rootPosition, Quaternion[] localRotations, float seconds)
        {
            int bones = _targetRotations.Length / 4;
            if (localRotations.Length != bones) throw new ArgumentException($"expected {bones} rotations, one per bone of Bones", nameof(localRotations));
            using (s_Request.Auto())
            {
                float length = Length(seconds);
                _targetRoot[0] = rootPosition.x;
                _targetRoot[1] = rootPosition.y;
                _targetRoot[2] = rootPosition.z;
                for (int b = 0; b < localRotations.Length; b++) UnityPoses.Write(localRotations[b], _targetRotations, 4 * b);
                Showed();
                return _character.RequestTransition(_targetRoot, _targetRotations, length);
            }
        }

        /// <summary>
        /// A hand-off into state <paramref name="stateHash"/> on <paramref name="layer"/>, arriving at <paramref name="timeInState"/>
        /// seconds into it; <paramref name="stateArgument"/> names the caller's argument (<c>stateName</c> or <c>stateHash</c>) in a refusal.
        /// </summary>
        private int State(int stateHash, string stateArgument, int layer, float timeInState, float seconds)
        {
            if (_animator.runtimeAnimatorController == null) throw new InvalidOperationException($"{_component.name}: the Animator has no Animator Controller; assign one before handing over to its states");
            int layers = _animator.layerCount;
            if (layer >= layers) throw new ArgumentOutOfRangeException(nameof(layer), layer, $"expected a layer of the Animator Controller (0–{layers - 1})");
            if (!_animator.HasState(layer, stateHash)) throw new ArgumentException($"the Animator Controller has no such state on layer {layer}; expected a state's name or full path (\"Base Layer.Roll\"), or its Animator.StringToHash", stateArgument);
            using (s_Request.Auto())
            {
                float length = Length(seconds);
                Showed();
                var state = new StateTarget(layer, stateHash, timeInState);
                int id = _character.RequestState(state, length, this);
                // Read in this frame's evaluation rather than after the next frame's (the frame output asks again until it is read).
                _binder.SampleState(state);
                return id;
            }
        }

        // The request's length: the settings' default for ≤ 0 (NaN was refused by the caller).
        private float Length(float seconds)
        {
            float length = seconds > 0 ? seconds : _settings.DefaultTransitionSeconds;
            _warnings.Warn(_character.Player, length, _component);
            return length;
        }

        // The pose shown last frame goes into the history before the request reads it, and the target into the same
        // root-motion space, from where the character stands now.
        private void Showed() => _character.Showed(UnityPoses.Place(_animator.transform), _animator.applyRootMotion, _binder.Shown);
    }
}
