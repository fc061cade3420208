#nullable enable
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Unity;
using UnityEngine;

namespace DeltaInterpolator.Samples.Demo
{
    /// <summary>
    /// The demo scene's controls: the same keys drive two characters that play the same Animator Controller (idle, walk,
    /// jump), side by side — one with Unity's own crossfades, one whose Animator transitions the <see cref="MotionInbetweener"/>
    /// replaces with neural in-betweens (its settings' neural transitions, no code). <b>W</b> walks or stops, <b>Space</b> jumps,
    /// <b>R</b> puts both back where they started; the camera follows them.
    /// </summary>
    /// <remarks>
    /// Keys are read through IMGUI events (<c>OnGUI</c>, <c>Event.current</c>), which Unity delivers whatever Active Input
    /// Handling is set to, so the demo needs no input package and no setting. Only Animator parameters are set here
    /// (<c>Walk</c>, <c>Jump</c>): what differs between the two characters is the transition, nothing else.
    /// </remarks>
    public sealed class NeuralTransitionDemo : MonoBehaviour
    {
        [Tooltip("The character that keeps Unity's crossfades.")]
        [SerializeField] private Animator? _crossfade = null;

        [Tooltip("The character whose Animator transitions are neural (it has a Motion Inbetweener).")]
        [SerializeField] private Animator? _neural = null;

        [Tooltip("The camera that follows the two characters.")]
        [SerializeField] private Camera? _camera = null;

        [SerializeField] private KeyCode _walkKey = KeyCode.W;
        [SerializeField] private KeyCode _jumpKey = KeyCode.Space;
        [SerializeField] private KeyCode _resetKey = KeyCode.R;

        private bool _walking;
        private Vector3 _crossfadeStart;
        private Vector3 _neuralStart;
        private Quaternion _crossfadeFacing;
        private Quaternion _neuralFacing;
        private Vector3 _cameraOffset;

        private void Start()
        {
            if (_crossfade == null || _neural == null) return;
            _crossfadeStart = _crossfade.transform.position;
            _neuralStart = _neural.transform.position;
            _crossfadeFacing = _crossfade.transform.rotation;
            _neuralFacing = _neural.transform.rotation;
            if (_camera != null)
            {
                Vector3 mid = Midpoint();
                Vector3 c = _camera.transform.position;
                _cameraOffset = new Vector3(c.x - mid.x, c.y - mid.y, c.z - mid.z);
            }
        }

        /// <summary>Starts or stops both characters walking (the W key and the button call this).</summary>
        public void ToggleWalk()
        {
            _walking = !_walking;
            foreach (Animator a in Both()) a.SetBool("Walk", _walking);
        }

        /// <summary>Both characters jump (Space and the button).</summary>
        public void Jump()
        {
            foreach (Animator a in Both()) a.SetTrigger("Jump");
        }

        /// <summary>Both characters back where they started, idle.</summary>
        public void ResetPlaces()
        {
            if (_walking) ToggleWalk();
            if (_crossfade != null) _crossfade.transform.SetPositionAndRotation(_crossfadeStart, _crossfadeFacing);
            if (_neural != null) _neural.transform.SetPositionAndRotation(_neuralStart, _neuralFacing);
        }

        // After the characters moved this frame (root motion), so the camera does not lag a frame behind them.
        private void LateUpdate()
        {
            if (_camera == null || _crossfade == null || _neural == null) return;
            Vector3 mid = Midpoint();
            _camera.transform.position = new Vector3(mid.x + _cameraOffset.x, mid.y + _cameraOffset.y, mid.z + _cameraOffset.z);
        }

        private Vector3 Midpoint()
        {
            Vector3 a = _crossfade!.transform.position;
            Vector3 b = _neural!.transform.position;
            return new Vector3(0.5f * (a.x + b.x), 0.5f * (a.y + b.y), 0.5f * (a.z + b.z));
        }

        private Animator[] Both() => _crossfade != null && _neural != null ? new[] { _crossfade, _neural } : new Animator[0];

        private void OnGUI()
        {
            Event e = Event.current;
            if (e.type == EventType.KeyDown)
            {
                if (e.keyCode == _walkKey) ToggleWalk();
                else if (e.keyCode == _jumpKey) Jump();
                else if (e.keyCode == _resetKey) ResetPlaces();
                if (e.keyCode == _walkKey || e.keyCode == _jumpKey || e.keyCode == _resetKey) e.Use();
            }

            GUILayout.BeginArea(new Rect(16, 16, 460, 210), GUI.skin.box);
            GUILayout.Label("Δ-Interpolator demo: the same controller, the same keys");
            GUILayout.Label("Left: Unity's crossfade.   Right: neural transitions.");
            MotionInbetweener? inbetweener = _neural != null ? _neural.GetComponent<MotionInbetweener>() : null;
            string state = inbetweener == null ? "no Motion Inbetweener" : inbetweener.State == PlaybackState.Running ? "running" : inbetweener.State + ": " + inbetweener.FailureReason;
            GUILayout.Label("Neural character: " + state);
            if (GUILayout.Button(_walking ? $"Stop ({_walkKey})" : $"Walk ({_walkKey})", GUILayout.Height(28))) ToggleWalk();
            if (GUILayout.Button($"Jump ({_jumpKey})", GUILayout.Height(28))) Jump();
            if (GUILayout.Button($"Back to the start ({_resetKey})", GUILayout.Height(24))) ResetPlaces();
            GUILayout.EndArea();
        }
    }
}
