using UnityEngine;

namespace UnityEditor.Animations
{
    // source: unity:Editor/Mono/Animation/AnimatorController.cs
    public sealed partial class AnimatorController : RuntimeAnimatorController
    {
        public static AnimatorController CreateAnimatorControllerAtPathWithClip(string path, AnimationClip clip) => throw null!;

        public static AnimatorController CreateAnimatorControllerAtPath(string path) => throw null!;

        public void AddParameter(string name, AnimatorControllerParameterType type) => throw null!;

        // source: unity:Editor/Mono/AnimatorController.bindings.cs
        public AnimatorControllerLayer[] layers { get => throw null!; set => throw null!; }
    }

    // source: unity:Editor/Mono/AnimatorControllerLayer.bindings.cs
    public partial class AnimatorControllerLayer
    {
        public bool iKPass { get => throw null!; set => throw null!; }

        public AnimatorStateMachine stateMachine { get => throw null!; set => throw null!; }
    }

    // source: unity:Editor/Mono/StateMachine.bindings.cs
    public enum AnimatorConditionMode
    {
        If = 1,
        IfNot = 2,
        Greater = 3,
        Less = 4,
        Equals = 6,
        NotEqual = 7,
    }

    // source: unity:Editor/Mono/StateMachine.bindings.cs
    public partial class AnimatorTransitionBase : Object
    {
        // source: unity:Editor/Mono/Animation/StateMachine.cs
        public void AddCondition(AnimatorConditionMode mode, float threshold, string parameter) => throw null!;
    }

    // source: unity:Editor/Mono/StateMachine.bindings.cs
    public partial class AnimatorStateTransition : AnimatorTransitionBase
    {
        public float duration { get => throw null!; set => throw null!; }

        public float exitTime { get => throw null!; set => throw null!; }

        public bool hasExitTime { get => throw null!; set => throw null!; }

        public bool hasFixedDuration { get => throw null!; set => throw null!; }
    }

    // source: unity:Editor/Mono/StateMachine.bindings.cs
    public sealed partial class AnimatorState : Object
    {
        public Motion motion { get => throw null!; set => throw null!; }

        public string tag { get => throw null!; set => throw null!; }

        // source: unity:Editor/Mono/Animation/StateMachine.cs
        public AnimatorStateTransition AddTransition(AnimatorState destinationState) => throw null!;
    }

    // source: unity:Editor/Mono/StateMachine.bindings.cs
    public sealed partial class AnimatorStateMachine : Object
    {
        public AnimatorState defaultState { get => throw null!; set => throw null!; }

        // source: unity:Editor/Mono/Animation/StateMachine.cs
        public AnimatorState AddState(string name) => throw null!;
    }
}
