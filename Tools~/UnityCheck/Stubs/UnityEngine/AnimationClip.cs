namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/AnimationClip.bindings.cs
    public sealed partial class AnimationClip : Motion
    {
        public void SampleAnimation(GameObject go, float time) => throw null!;
    }
}
