using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>Whether transitions into a state with a <see cref="NeuralTransition"/> become neural.</summary>
    public enum NeuralTransitionMode
    {
        /// <summary>Transitions into the state become neural even when the layer's tags would keep the crossfade.</summary>
        OptIn = 0,

        /// <summary>Transitions into the state keep the crossfade.</summary>
        OptOut = 1,
    }

    /// <summary>
    /// Opts one Animator state in or out of neural transitions (<see cref="InbetweenerSettings.NeuralTransitions"/>):
    /// add it to the state in the Animator window (<i>Add Behaviour</i>). No code is needed; the character's
    /// <see cref="MotionInbetweener"/> learns of the state when a transition into it starts.
    /// </summary>
    /// <remarks>
    /// The Animator calls <c>OnStateEnter</c> when it starts evaluating the state, i.e. in the animation update in which
    /// a transition into it starts, before the component's next <c>Update</c> reads the transition, so the choice is
    /// known when the component decides. The component's own state reader (a copy of the controller held in a state)
    /// enters states too; marking a state twice changes nothing.
    /// </remarks>
    public sealed class NeuralTransition : StateMachineBehaviour
    {
        [SerializeField]
        [Tooltip("Opt In: transitions into this state become neural even when the layer's tags exclude it. Opt Out: they keep the crossfade.")]
        private NeuralTransitionMode mode = NeuralTransitionMode.OptIn;

        /// <summary>Whether transitions into this state become neural.</summary>
        public NeuralTransitionMode Mode
        {
            get => mode;
            set => mode = value;
        }

        public override void OnStateEnter(Animator animator, AnimatorStateInfo stateInfo, int layerIndex)
        {
            MotionInbetweener inbetweener = animator.GetComponent<MotionInbetweener>();
            if (inbetweener != null) inbetweener.MarkState(stateInfo.fullPathHash, layerIndex, mode);
        }
    }
}
