namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public enum AnimatorUpdateMode
    {
        Normal = 0,
        Fixed = 1,
        UnscaledTime = 2,

        [System.Obsolete("Enum member AnimatorUpdateMode.AnimatePhysics has been deprecated. Use AnimatorUpdateMode.Fixed to evaluate in FixedUpdate time and Animator.animatePhysics to sync transforms for physics. (UnityUpgradable) -> Fixed", true)]
        AnimatePhysics = 1,
    }

    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public enum AvatarIKGoal
    {
        LeftFoot = 0,
        RightFoot = 1,
        LeftHand = 2,
        RightHand = 3,
    }

    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public partial class Animator : Behaviour
    {
        public bool isHuman => throw null!;

        public bool applyRootMotion { get => throw null!; set => throw null!; }

        // UnityCsReference 6000.0 Modules/Animation/ScriptBindings/Animator.bindings.cs:310-315 (a generic rig with a root motion node, or a humanoid)
        public bool hasRootMotion => throw null!;

        public Vector3 velocity => throw null!;

        public Avatar avatar { get => throw null!; set => throw null!; }

        public AnimatorUpdateMode updateMode { get => throw null!; set => throw null!; }

        public RuntimeAnimatorController runtimeAnimatorController { get => throw null!; set => throw null!; }

        public Transform GetBoneTransform(HumanBodyBones humanBoneId) => throw null!;

        public void SetIKPosition(AvatarIKGoal goal, Vector3 goalPosition) => throw null!;

        public void SetIKPositionWeight(AvatarIKGoal goal, float value) => throw null!;
    }
}
