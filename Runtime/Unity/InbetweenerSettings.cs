using System;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// How a <see cref="MotionInbetweener"/> runs: which model on which inference engine, which rig its
    /// bones form and how they map to the model's joints, and how transitions blend with the character's own animation. One asset
    /// can be shared by many characters (they then share one loaded model).
    /// </summary>
    [CreateAssetMenu(fileName = "InbetweenerSettings", menuName = "Δ-Interpolator/In-betweener Settings", order = 411)]
    public sealed class InbetweenerSettings : ScriptableObject
    {
        [SerializeField]
        [Tooltip("The in-betweening model asset (Assets > Create > Δ-Interpolator > In-betweening Model, pointing at the exported .onnx graphs).")]
        private InbetweeningModel? model = null;

        [SerializeField]
        [Tooltip("The inference engine, by name: \"Sentis\" (CPU) or \"Sentis GPU\" (compute shaders); another engine's name once its assembly registers it.")]
        private string backend = "Sentis";

        [SerializeField]
        [Tooltip("Automatic: Humanoid when the Animator has a humanoid avatar, else Generic. Humanoid: bones and T-pose from the Animator's humanoid avatar. Generic: bones found by the joint map's names under the Animator.")]
        private CharacterRigKind rig = CharacterRigKind.Automatic;

        [SerializeField]
        [Tooltip("Generic rigs: the bone-naming convention (LaFAN1, CMU, Mixamo, Poser).")]
        private BuiltInJointMap jointMap = BuiltInJointMap.Lafan1;

        [SerializeField]
        [Tooltip("Generic rigs: a JSON joint map, {\"Hips\": \"pelvis\", \"LeftToe\": null, ...}; model joints it does not name take the convention's names.")]
        private TextAsset? jointMapJson = null;

        [SerializeField]
        [Tooltip("Generic rigs: bones whose names differ from the joint map's (model joint → bone name).")]
        private JointBinding[] joints = new JointBinding[0];

        [SerializeField]
        [Tooltip("Generic rigs: the reference pose compared with the model's T-pose (each mapped bone within 25°).")]
        private ReferencePoseSource referencePose = ReferencePoseSource.ModelAxes;

        [SerializeField]
        [Tooltip("Reference pose 'Clip Frame': the clip that shows a T-pose.")]
        private AnimationClip? referenceClip = null;

        [SerializeField]
        [Tooltip("Reference pose 'Clip Frame': the time (seconds) at which the clip shows it.")]
        private float referenceClipTime = 0f;

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

        [SerializeField]
        [Tooltip("Hold planted feet still during transitions and solve the legs to them (two-bone IK), so feet do not slide.")]
        private bool lockFeet = true;

        [SerializeField]
        [Tooltip("Load the model as soon as a scene that uses these settings has loaded (a character in it, or a prefab a spawner in it references), so the first character to start later does not wait for a synchronous load mid-game. Off: the first character to start loads it.")]
        private bool loadOnAwake = true;

        [SerializeField]
        [Tooltip("Neural Animator transitions: per controller layer, the Animator's own transitions (within a duration range, filtered by state tags) become in-betweens that end on the next state's pose. Empty, or every entry disabled (the default: the base layer, off): every transition stays a crossfade.")]
        // One entry for the base layer, off: the inspector shows the switch, and nothing changes until it is ticked.
        private NeuralTransitionLayer[] neuralTransitions = { new NeuralTransitionLayer { layer = 0, enabled = false } };

        /// <summary>The model.</summary>
        public InbetweeningModel? Model => model;

        /// <summary>Whether the model is loaded when a scene that uses these settings has loaded (<see cref="Preload"/>), not when the first character starts.</summary>
        public bool LoadOnAwake => loadOnAwake;

        /// <summary>True while these settings hold their model loaded (<see cref="Preload"/>, or <see cref="LoadOnAwake"/>).</summary>
        public bool IsPreloaded => ModelPreloads.IsPreloaded(this);

        /// <summary>
        /// Loads the model on the settings' engine now (e.g. behind a loading screen) and holds it, so characters using these
        /// settings start without loading it; they share it. Held until <see cref="ReleasePreload"/>, the settings being
        /// unloaded, or the end of play. Does nothing when already held.
        /// </summary>
        /// <exception cref="InvalidOperationException">The settings have no model, or their inference engine is not installed.</exception>
        /// <exception cref="Core.Inference.ModelContractException">The model cannot be loaded or does not fit its contract.</exception>
        public void Preload() => ModelPreloads.Preload(this);

        /// <summary>Lets the model <see cref="Preload"/> loaded go: it is disposed once no character uses it either.</summary>
        public void ReleasePreload() => ModelPreloads.Release(this);

        /// <summary>The inference engine's name (<see cref="InferenceBackends"/>).</summary>
        public string Backend => backend;

        /// <summary>How the character's bones and reference pose are found (<see cref="RigOf"/> decides <see cref="CharacterRigKind.Automatic"/>).</summary>
        public CharacterRigKind Rig => rig;

        /// <summary>The rig <paramref name="animator"/> is read as: <see cref="Rig"/>, with <see cref="CharacterRigKind.Automatic"/> decided by its avatar.</summary>
        public CharacterRigKind RigOf(Animator animator)
        {
            if (animator == null) throw new ArgumentNullException(nameof(animator));
            if (rig != CharacterRigKind.Automatic) return rig;
            return animator.isHuman ? CharacterRigKind.Humanoid : CharacterRigKind.Generic;
        }

        /// <summary>Generic rigs: the bone-naming convention.</summary>
        public BuiltInJointMap JointMap => jointMap;

        /// <summary>Generic rigs: a JSON joint map, or null.</summary>
        public TextAsset? JointMapJson => jointMapJson;

        /// <summary>Generic rigs: bones whose names differ from the joint map's.</summary>
        public JointBinding[] Joints => joints;

        /// <summary>Generic rigs: where the reference pose comes from.</summary>
        public ReferencePoseSource ReferencePose => referencePose;

        /// <summary>Reference pose <see cref="ReferencePoseSource.ClipFrame"/>: the clip.</summary>
        public AnimationClip? ReferenceClip => referenceClip;

        /// <summary>Reference pose <see cref="ReferencePoseSource.ClipFrame"/>: the time in the clip (seconds).</summary>
        public float ReferenceClipTime => referenceClipTime;

        /// <summary>Seconds a transition takes when a request gives no length.</summary>
        public float DefaultTransitionSeconds => defaultTransitionSeconds;

        /// <summary>Seconds of blend-in after a request.</summary>
        public float BlendInSeconds => blendInSeconds;

        /// <summary>Seconds of blend-out after the target.</summary>
        public float BlendOutSeconds => blendOutSeconds;

        /// <summary>Past model frames fed to the network (0: the model's trained maximum).</summary>
        public int PastFrames => pastFrames;

        /// <summary>Whether transitions hold planted feet still (<see cref="Core.Playback.PlaybackSettings.LockFeet"/>).</summary>
        public bool LockFeet => lockFeet;

        /// <summary>
        /// Neural Animator transitions, one entry per controller layer (none enabled: the controller's transitions stay crossfades; new
        /// settings hold the base layer's entry, disabled).
        /// The component reads them when it starts and when they are edited.
        /// </summary>
        public NeuralTransitionLayer[] NeuralTransitions => neuralTransitions ?? new NeuralTransitionLayer[0];

        /// <summary>Replaces <see cref="NeuralTransitions"/> from code (e.g. for settings made with <c>CreateInstance</c>); components using the asset apply it at their next frame.</summary>
        /// <exception cref="ArgumentNullException"><paramref name="layers"/> or an entry of it is null.</exception>
        /// <exception cref="ArgumentOutOfRangeException">An entry has a negative layer or duration, or a range whose end is below its start (the parameter names the entry and field).</exception>
        /// <exception cref="ArgumentException">Two entries name the same layer.</exception>
        public void SetNeuralTransitions(NeuralTransitionLayer[] layers)
        {
            CheckNeuralTransitions(layers, nameof(layers));
            neuralTransitions = (NeuralTransitionLayer[])layers.Clone();
            Changed?.Invoke(this);
        }

        /// <summary>Refuses entries no controller could meet, naming the entry and field (<paramref name="name"/>[i].field).</summary>
        internal static void CheckNeuralTransitions(NeuralTransitionLayer[] layers, string name)
        {
            if (layers == null) throw new ArgumentNullException(name);
            for (int i = 0; i < layers.Length; i++)
            {
                NeuralTransitionLayer layer = layers[i] ?? throw new ArgumentNullException($"{name}[{i}]", "expected an entry, not null");
                layer.Check($"{name}[{i}]");
                for (int j = 0; j < i; j++)
                {
                    if (layers[j].layer == layer.layer) throw new ArgumentException($"entries {j} and {i} both name controller layer {layer.layer}; expected one entry per layer", $"{name}[{i}].layer");
                }
            }
        }

        /// <summary>Raised when a field is edited (inspector, undo) in the Editor; components using the asset apply the change.</summary>
        internal event Action<InbetweenerSettings>? Changed;

        private void OnValidate() => Changed?.Invoke(this);

        // Loaded with a scene (or by a script): Load On Awake preloads it once the scene has loaded.
        private void OnEnable() => ModelPreloads.Loaded(this);

        private void OnDisable() => ModelPreloads.Unloaded(this);
    }
}
