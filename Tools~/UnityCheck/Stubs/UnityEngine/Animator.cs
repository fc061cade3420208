namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public partial class Animator : Behaviour
    {
        public bool isHuman => throw null!;

        public bool applyRootMotion { get => throw null!; set => throw null!; }

        public Avatar avatar { get => throw null!; set => throw null!; }

        public Transform GetBoneTransform(HumanBodyBones humanBoneId) => throw null!;
    }
}
