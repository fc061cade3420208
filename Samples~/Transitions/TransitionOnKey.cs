#nullable enable
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Unity;
using UnityEngine;

namespace DeltaInterpolator.Samples.Transitions
{
    /// <summary>
    /// Press a key and the character leaves whatever its Animator Controller plays, moving through neural
    /// in-betweens into <see cref="_target"/> at <see cref="_targetTime"/>, which it reaches after
    /// <see cref="_seconds"/> (<see cref="MotionInbetweener.RequestTransition(AnimationClip, float, float)"/>).
    /// Completion is logged from <see cref="MotionInbetweener.TransitionCompleted"/>. The request is
    /// refused (logged) while the component has no loaded model. Uses the legacy Input Manager (Project Settings →
    /// Player → Active Input Handling: "Input Manager (Old)" or "Both").
    /// </summary>
    [RequireComponent(typeof(MotionInbetweener))]
    public sealed class TransitionOnKey : MonoBehaviour
    {
        [Tooltip("The key that starts a transition.")]
        [SerializeField] private KeyCode _key = KeyCode.Space;

        [Tooltip("The clip to arrive in.")]
        [SerializeField] private AnimationClip? _target = null;

        [Tooltip("Time in the target clip (seconds) of the pose to arrive at.")]
        [SerializeField] private float _targetTime = 0f;

        [Tooltip("Length of the transition in seconds (the model was trained on 5–39 frames at 30 fps: about 0.17–1.3 s).")]
        [SerializeField] private float _seconds = 0.5f;

        private MotionInbetweener? _animator;
        private int _lastRequest = -1;

        private void OnEnable()
        {
            _animator = GetComponent<MotionInbetweener>();
            _animator.TransitionCompleted += OnTransitionCompleted;
        }

        private void OnDisable()
        {
            if (_animator != null) _animator.TransitionCompleted -= OnTransitionCompleted;
        }

        private void Update()
        {
            if (_animator == null || _target == null || !Input.GetKeyDown(_key)) return;
            try
            {
                _lastRequest = _animator.RequestTransition(_target, _targetTime, _seconds);
            }
            catch (System.InvalidOperationException e)
            {
                Debug.Log($"{name}: no transition: {e.Message}");
            }
        }

        private void OnTransitionCompleted(TransitionCompletion completion)
        {
            string how = completion.ReachedTarget ? "reached its target" : "was cancelled or replaced";
            string latest = completion.RequestId == _lastRequest ? " (the latest request)" : "";
            Debug.Log($"{name}: transition {completion.RequestId}{latest} into {(_target != null ? _target.name : "?")} at {_targetTime:0.00} s {how} at {completion.Time:0.00} s.");
        }
    }
}
