// Runtime/Unity's use of UnityEngine.Object; other assemblies' members go in their own partial files.
namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/UnityEngineObject.bindings.cs
    public partial class Object
    {
        public string name { get => throw null!; set => throw null!; }

        public static bool operator ==(Object x, Object y) => throw null!;

        public static bool operator !=(Object x, Object y) => throw null!;
    }
}
