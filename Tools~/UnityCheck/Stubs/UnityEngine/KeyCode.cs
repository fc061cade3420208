namespace UnityEngine
{
    // Only the keys the sample scripts use (an enum cannot be partial).
    // source: unity:Runtime/Export/Input/KeyCode.cs
    public enum KeyCode
    {
        Space = 32,
        R = 114,
        W = 119,
    }
}
