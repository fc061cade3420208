#nullable enable
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Unity;
using UnityEngine;

namespace DeltaInterpolator.Samples.Transitions
{
    /// <summary>
    /// Press a key and the character leaves whatever its Animator Controller plays, moving through neural
    /// in-betweens into the controller's state <see cref="_targetState"/> at <see cref="_targetTime"/> seconds into it,
    /// which it reaches after <see cref="_seconds"/> and then plays on
    /// (<see cref="MotionInbetweener.RequestTransition(string, int, float, float)"/>: the hand-off). Without a state it
    /// visits the pose of the clip <see cref="_target"/> instead and lets the controller take back over
    /// (<see cref="MotionInbetweener.RequestTransition(AnimationClip, float, float)"/>).
    /// Completion is logged from <see cref="MotionInbetweener.TransitionCompleted"/>. The request is
    /// refused (logged) while the component has no loaded model. Reads the key through the legacy Input Manager
    /// (Project Settings → Player → Active Input Handling: "Input Manager (Old)" or "Both"); where that setting is
    /// "Input System Package (New)" alone, UnityEngine.Input throws, so the script compiles without it and warns once.
    /// </summary>
    [RequireComponent(typeof(MotionInbetweener))]
    public sealed class TransitionOnKey : MonoBehaviour
    {
        [Tooltip("The key that starts a transition.")]
        [SerializeField] private KeyCode _key = KeyCode.Space;

        [Tooltip("The Animator Controller state to hand over to (its name, e.g. Roll, or full path, e.g. Base Layer.Roll); it plays on after the transition.")]
        [SerializeField] private string _targetState = "";

        [Tooltip("The controller layer of the target state (0: the base layer).")]
        [SerializeField] private int _layer = 0;

        [Tooltip("Without a target state: a clip whose pose to visit (the controller then takes back over).")]
        [SerializeField] private AnimationClip? _target = null;

        [Tooltip("Time in the target state or clip (seconds) of the pose to arrive at.")]
        [SerializeField] private float _targetTime = 0f;

        [Tooltip("Length of the transition in seconds (the model was trained on 5–39 frames at 30 fps: about 0.17–1.3 s).")]
        [SerializeField] private float _seconds = 0.5f;

        private MotionInbetweener? _animator;
        private int _lastRequest = -1;

        private void OnEnable()
        {
            _animator = GetComponent<MotionInbetweener>();
            _animator.TransitionCompleted += OnTransitionCompleted;
#if !ENABLE_LEGACY_INPUT_MANAGER
            Debug.LogWarning($"{name}: Transition On Key reads its key ({_key}) through the Input Manager, which this project has switched off; set Project Settings → Player → Active Input Handling to \"Both\", or call Transition() from your own input code (e.g. when Keyboard.current.spaceKey.wasPressedThisFrame).", this);
#endif
        }

        private void OnDisable()
        {
            if (_animator != null) _animator.TransitionCompleted -= OnTransitionCompleted;
        }

        private void Update()
        {
#if ENABLE_LEGACY_INPUT_MANAGER
            if (Input.GetKeyDown(_key)) Transition();
#endif
        }

        /// <summary>Starts the transition (the key does this; call it from a UI button or your own input code).</summary>
        public void Transition()
        {
            if (_animator == null) return;
            try
            {
                if (!string.IsNullOrEmpty(_targetState)) _lastRequest = _animator.RequestTransition(_targetState, _layer, _targetTime, _seconds);
                else if (_target != null) _lastRequest = _animator.RequestTransition(_target, _targetTime, _seconds);
            }
            catch (System.InvalidOperationException e)
            {
                Debug.Log($"{name}: no transition: {e.Message}");
            }
            catch (System.ArgumentException e)
            {
                // An unknown state or layer, a negative time: the message names the setting to fix.
                Debug.LogWarning($"{name}: no transition: {e.Message}", this);
            }
        }

        private void OnTransitionCompleted(TransitionCompletion completion)
        {
            string how = completion.ReachedTarget ? "reached its target" : "was cancelled or replaced";
            string latest = completion.RequestId == _lastRequest ? " (the latest request)" : "";
            string into = !string.IsNullOrEmpty(_targetState) ? _targetState : _target != null ? _target.name : "?";
            Debug.Log($"{name}: transition {completion.RequestId}{latest} into {into} at {_targetTime:0.00} s {how} at {completion.Time:0.00} s.");
        }
    }
}
