namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/AvatarMask.bindings.cs
    public enum AvatarMaskBodyPart
    {
        Root = 0,
        Body = 1,
        Head = 2,
        LeftLeg = 3,
        RightLeg = 4,
        LeftArm = 5,
        RightArm = 6,
        LeftFingers = 7,
        RightFingers = 8,
        LeftFootIK = 9,
        RightFootIK = 10,
        LeftHandIK = 11,
        RightHandIK = 12,
        LastBodyPart = 13,
    }

    // source: unity:Modules/Animation/ScriptBindings/AvatarMask.bindings.cs
    public sealed partial class AvatarMask : Object
    {
        public AvatarMask() => throw null!;

        public bool GetHumanoidBodyPartActive(AvatarMaskBodyPart index) => throw null!;

        public int transformCount { get => throw null!; set => throw null!; }

        public string GetTransformPath(int index) => throw null!;

        public bool GetTransformActive(int index) => throw null!;

        public void SetTransformPath(int index, string path) => throw null!;

        public void SetTransformActive(int index, bool value) => throw null!;
    }
}
