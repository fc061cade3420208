namespace UnityEngine
{
    // source: unity:Modules/IMGUI/GUI.cs
    public partial class GUI
    {
        public static GUISkin skin { get => throw null!; set => throw null!; }
    }

    // source: unity:Modules/IMGUI/GUISkin.cs
    public sealed partial class GUISkin : ScriptableObject
    {
        public GUIStyle box { get => throw null!; set => throw null!; }
    }

    // source: unity:Modules/IMGUI/GUIStyle*.cs
    public sealed partial class GUIStyle
    {
    }

    // source: unity:Modules/IMGUI/Event*.cs
    public sealed partial class Event
    {
        public static Event current { get => throw null!; set => throw null!; }

        public EventType type { get => throw null!; set => throw null!; }

        public KeyCode keyCode { get => throw null!; set => throw null!; }

        public void Use() => throw null!;
    }

    // Only the members the package uses (an enum cannot be partial).
    // source: unity:Modules/IMGUI/EventEnums.cs
    public enum EventType
    {
        KeyDown = 4,
    }

    // source: unity:Runtime/Export/Geometry/Rect.cs
    public partial struct Rect
    {
        public Rect(float x, float y, float width, float height) => throw null!;
    }
}
