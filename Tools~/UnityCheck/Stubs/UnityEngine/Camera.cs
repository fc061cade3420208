namespace UnityEngine
{
    // source: unity:Runtime/Export/Camera/Camera.bindings.cs
    public sealed partial class Camera : Behaviour
    {
    }
}
