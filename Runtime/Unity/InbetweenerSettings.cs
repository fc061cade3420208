using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// How a <see cref="MotionInbetweener"/> runs: which model on which inference engine, how its bones
    /// map to the model's joints, and how transitions blend with the character's own animation. One asset
    /// can be shared by many characters (they then share one loaded model).
    /// </summary>
    [CreateAssetMenu(fileName = "InbetweenerSettings", menuName = "Δ-Interpolator/In-betweener Settings", order = 411)]
    public sealed class InbetweenerSettings : ScriptableObject
    {
        [SerializeField]
        [Tooltip("The in-betweening model (created when an exported .onnx is imported).")]
        private InbetweeningModel? model = null;

        [SerializeField]
        [Tooltip("The inference engine, by name (\"Sentis\" with com.unity.ai.inference installed).")]
        private string backend = "Sentis";

        [SerializeField]
        [Tooltip("Bones whose names differ from the model's joints. Joints not listed are found by their own name under the Animator.")]
        private JointBinding[] joints = new JointBinding[0];

        [SerializeField]
        [Tooltip("Seconds a transition takes when a request gives no length.")]
        private float defaultTransitionSeconds = 0.5f;

        [SerializeField]
        [Tooltip("Seconds over which a transition takes over from the character's animation after a request.")]
        private float blendInSeconds = 0.1f;

        [SerializeField]
        [Tooltip("Seconds over which the character's animation takes back over after the target pose.")]
        private float blendOutSeconds = 0.2f;

        [SerializeField]
        [Tooltip("Past model frames fed to the network; 0 uses the most the model was trained with.")]
        private int pastFrames = 0;

        /// <summary>The model.</summary>
        public InbetweeningModel? Model => model;

        /// <summary>The inference engine's name (<see cref="InferenceBackends"/>).</summary>
        public string Backend => backend;

        /// <summary>Bones whose names differ from the model's joints.</summary>
        public JointBinding[] Joints => joints;

        /// <summary>Seconds a transition takes when a request gives no length.</summary>
        public float DefaultTransitionSeconds => defaultTransitionSeconds;

        /// <summary>Seconds of blend-in after a request.</summary>
        public float BlendInSeconds => blendInSeconds;

        /// <summary>Seconds of blend-out after the target.</summary>
        public float BlendOutSeconds => blendOutSeconds;

        /// <summary>Past model frames fed to the network (0: the model's trained maximum).</summary>
        public int PastFrames => pastFrames;
    }
}
