namespace UnityEngine
{
    // source: unity:Runtime/Export/Animation/AnimationCurve.bindings.cs
    public enum WeightedMode
    {
        None = 0,
        In = 1 << 0,
        Out = 1 << 1,
        Both = In | Out
    }
}
