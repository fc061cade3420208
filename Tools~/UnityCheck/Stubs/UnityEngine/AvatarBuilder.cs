namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    public partial struct SkeletonBone
    {
        public string name;
        public Vector3 position;
        public Quaternion rotation;
        public Vector3 scale;
    }

    // source: unity:Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    public partial struct HumanLimit
    {
        public bool useDefaultValues { get => throw null!; set => throw null!; }
    }

    // source: unity:Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    public partial struct HumanBone
    {
        public HumanLimit limit;

        public string boneName { get => throw null!; set => throw null!; }

        public string humanName { get => throw null!; set => throw null!; }
    }

    // source: unity:Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    public partial struct HumanDescription
    {
        public HumanBone[] human;
        public SkeletonBone[] skeleton;

        public float upperArmTwist { get => throw null!; set => throw null!; }

        public float lowerArmTwist { get => throw null!; set => throw null!; }

        public float upperLegTwist { get => throw null!; set => throw null!; }

        public float lowerLegTwist { get => throw null!; set => throw null!; }

        public float armStretch { get => throw null!; set => throw null!; }

        public float legStretch { get => throw null!; set => throw null!; }

        public float feetSpacing { get => throw null!; set => throw null!; }

        public bool hasTranslationDoF { get => throw null!; set => throw null!; }
    }

    // source: unity:Modules/Animation/ScriptBindings/AvatarBuilder.bindings.cs
    public partial class AvatarBuilder
    {
        public static Avatar BuildHumanAvatar(GameObject go, HumanDescription humanDescription) => throw null!;

        public static Avatar BuildGenericAvatar(GameObject go, string rootMotionTransformName) => throw null!;
    }
}
