namespace UnityEngine
{
    // source: unity:Modules/IMGUI/GUILayoutOption.cs
    public sealed partial class GUILayoutOption
    {
    }
}
