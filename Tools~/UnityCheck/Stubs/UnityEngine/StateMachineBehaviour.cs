namespace UnityEngine
{
    // source: unity:Modules/Animation/Managed/StateMachineBehaviour.cs
    public abstract partial class StateMachineBehaviour : ScriptableObject
    {
        public virtual void OnStateEnter(Animator animator, AnimatorStateInfo stateInfo, int layerIndex) => throw null!;
    }
}
