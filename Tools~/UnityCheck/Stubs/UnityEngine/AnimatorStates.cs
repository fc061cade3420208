namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public enum AnimatorControllerParameterType
    {
        Float = 1,
        Int = 3,
        Bool = 4,
        Trigger = 9,
    }

    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public enum DurationUnit
    {
        Fixed,
        Normalized,
    }

    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public partial struct AnimatorStateInfo
    {
        public int fullPathHash => throw null!;

        public int shortNameHash => throw null!;

        public float normalizedTime => throw null!;

        public float length => throw null!;

        public float speed => throw null!;

        public float speedMultiplier => throw null!;

        public int tagHash => throw null!;

        public bool loop => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public partial struct AnimatorTransitionInfo
    {
        public int fullPathHash => throw null!;

        public int nameHash => throw null!;

        public DurationUnit durationUnit => throw null!;

        public float duration => throw null!;

        public float normalizedTime => throw null!;

        public bool anyState => throw null!;
    }

    // source: unity:Modules/Animation/ScriptBindings/AnimatorControllerParameter.bindings.cs
    public partial class AnimatorControllerParameter
    {
        public int nameHash => throw null!;

        public AnimatorControllerParameterType type { get => throw null!; set => throw null!; }
    }

    // The members that read a controller's states and transitions and put a layer in a state (issue 27's hand-off).
    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public partial class Animator
    {
        public int layerCount => throw null!;

        public int parameterCount => throw null!;

        public AnimatorControllerParameter GetParameter(int index) => throw null!;

        public float GetFloat(int id) => throw null!;

        public bool GetBool(int id) => throw null!;

        public int GetInteger(int id) => throw null!;

        public float GetLayerWeight(int layerIndex) => throw null!;

        public bool IsInTransition(int layerIndex) => throw null!;

        public AnimatorStateInfo GetCurrentAnimatorStateInfo(int layerIndex) => throw null!;

        public AnimatorStateInfo GetNextAnimatorStateInfo(int layerIndex) => throw null!;

        public AnimatorTransitionInfo GetAnimatorTransitionInfo(int layerIndex) => throw null!;

        public bool HasState(int layerIndex, int stateID) => throw null!;

        public void PlayInFixedTime(int stateNameHash, int layer, float fixedTime) => throw null!;

        public static int StringToHash(string name) => throw null!;

        public void SetBool(string name, bool value) => throw null!;

        public void SetTrigger(string name) => throw null!;
    }
}
