#nullable enable
using DeltaInterpolator.Unity;
using UnityEngine;

namespace DeltaInterpolator.Samples.Transitions
{
    /// <summary>
    /// Press a key and the character leaves whatever its Animator Controller plays, moving through neural
    /// in-betweens into <see cref="_target"/> at <see cref="_targetTime"/>, which it reaches after
    /// <see cref="_seconds"/>. Completion is logged. Uses the legacy Input Manager (Project Settings →
    /// Player → Active Input Handling: "Input Manager (Old)" or "Both").
    /// </summary>
    [RequireComponent(typeof(InbetweeningAnimator))]
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

        private InbetweeningAnimator? _animator;
        private int _requested;

        private void OnEnable()
        {
            _animator = GetComponent<InbetweeningAnimator>();
            _animator.TransitionCompleted += OnTransitionCompleted;
        }

        private void OnDisable()
        {
            if (_animator != null) _animator.TransitionCompleted -= OnTransitionCompleted;
        }

        private void Update()
        {
            if (_animator == null || _target == null || !Input.GetKeyDown(_key)) return;
            _requested++;
            _animator.RequestTransition(_target, _targetTime, _seconds);
        }

        private void OnTransitionCompleted()
        {
            Debug.Log($"{name}: transition {_requested} into {(_target != null ? _target.name : "?")} at {_targetTime:0.00} s completed.");
        }
    }
}
