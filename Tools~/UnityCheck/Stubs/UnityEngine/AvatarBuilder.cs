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
    public partial struct HumanDescription
    {
        public SkeletonBone[] skeleton;
    }
}
