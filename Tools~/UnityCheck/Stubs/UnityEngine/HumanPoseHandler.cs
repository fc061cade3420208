using System;

namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/HumanPoseHandler.bindings.cs
    public partial struct HumanPose
    {
        public Vector3 bodyPosition;
        public Quaternion bodyRotation;
        public float[] muscles;
    }

    // source: unity:Modules/Animation/ScriptBindings/HumanPoseHandler.bindings.cs
    public partial class HumanPoseHandler : IDisposable
    {
        public HumanPoseHandler(Avatar avatar, Transform root) => throw null!;

        public void Dispose() => throw null!;

        public void GetHumanPose(ref HumanPose humanPose) => throw null!;
    }
}
