#nullable enable
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Unity;
using UnityEngine;

namespace DeltaInterpolator.Samples.Demo
{
    /// <summary>
    /// The demo scene's controls: an on-screen button and a key (Space) send the character, through neural
    /// in-betweens, to the next of <see cref="_targetTimes"/> in <see cref="_target"/>, arriving after
    /// <see cref="_seconds"/>; the panel shows the component's state and the last transition's outcome.
    /// </summary>
    /// <remarks>
    /// Button and key are read through IMGUI events (<c>OnGUI</c>, <c>Event.current</c>), which Unity delivers
    /// whatever Active Input Handling is set to (Input Manager, Input System or both), so the demo needs no
    /// input package and no setting.
    /// </remarks>
    [RequireComponent(typeof(MotionInbetweener))]
    public sealed class NeuralTransitionDemo : MonoBehaviour
    {
        [Tooltip("The key that starts a transition (read through IMGUI events: works under either input setting).")]
        [SerializeField] private KeyCode _key = KeyCode.Space;

        [Tooltip("The clip whose poses the character transitions into.")]
        [SerializeField] private AnimationClip? _target = null;

        [Tooltip("Times in the target clip (seconds) of the poses to arrive at, used in turn.")]
        [SerializeField] private float[] _targetTimes = { 1.5f, 3.0f, 5.5f, 7.5f };

        [Tooltip("Length of each transition in seconds (the shipped model was trained on gaps of about 0.17-1.3 s).")]
        [SerializeField] private float _seconds = 0.6f;

        private MotionInbetweener? _inbetweener;
        private int _next;
        private string _last = "Press the button or Space.";

        private void OnEnable()
        {
            _inbetweener = GetComponent<MotionInbetweener>();
            _inbetweener.TransitionCompleted += OnCompleted;
        }

        private void OnDisable()
        {
            if (_inbetweener != null) _inbetweener.TransitionCompleted -= OnCompleted;
        }

        /// <summary>Sends the character to the next target pose (the button and the key call this).</summary>
        public void Transition()
        {
            if (_inbetweener == null || _target == null || _targetTimes.Length == 0) return;
            float time = _targetTimes[_next % _targetTimes.Length];
            _next++;
            try
            {
                int id = _inbetweener.RequestTransition(_target, time, _seconds);
                _last = $"Transition {id}: to {_target.name} at {time:0.0} s, arriving in {_seconds:0.00} s.";
            }
            catch (System.InvalidOperationException e)
            {
                _last = "No transition: " + e.Message;
            }
        }

        private void OnCompleted(TransitionCompletion completion)
        {
            _last = $"Transition {completion.RequestId} {(completion.ReachedTarget ? "reached its target" : "was replaced")} at {completion.Time:0.00} s.";
        }

        private void OnGUI()
        {
            Event e = Event.current;
            if (e.type == EventType.KeyDown && e.keyCode == _key)
            {
                Transition();
                e.Use();
            }

            GUILayout.BeginArea(new Rect(16, 16, 420, 160), GUI.skin.box);
            GUILayout.Label("Δ-Interpolator demo: neural in-betweening");
            string state = _inbetweener == null ? "no Motion Inbetweener" : _inbetweener.State == PlaybackState.Running ? "running" : _inbetweener.State + ": " + _inbetweener.FailureReason;
            GUILayout.Label("Component: " + state);
            if (GUILayout.Button($"Neural transition ({_key})", GUILayout.Height(32))) Transition();
            GUILayout.Label(_last);
            GUILayout.EndArea();
        }
    }
}
