using UnityEngine.Playables;

namespace UnityEngine.Animations
{
    // source: unity:Modules/Animation/ScriptBindings/AnimatorControllerPlayable.bindings.cs
    public partial struct AnimatorControllerPlayable : IPlayable
    {
        public static AnimatorControllerPlayable Create(PlayableGraph graph, RuntimeAnimatorController controller) => throw null!;

        public int GetLayerCount() => throw null!;

        public void SetLayerWeight(int layerIndex, float weight) => throw null!;

        public AnimatorStateInfo GetCurrentAnimatorStateInfo(int layerIndex) => throw null!;

        public void SetFloat(int id, float value) => throw null!;

        public void SetBool(int id, bool value) => throw null!;

        public void SetInteger(int id, int value) => throw null!;

        public void PlayInFixedTime(int stateNameHash, int layer, float fixedTime) => throw null!;
    }
}
