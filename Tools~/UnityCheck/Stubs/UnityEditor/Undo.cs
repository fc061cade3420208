using UnityEngine;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Undo/Undo.bindings.cs
    public partial class Undo
    {
        public static void RegisterCreatedObjectUndo(Object objectToUndo, string name) => throw null!;

        public static void RegisterCompleteObjectUndo(Object objectToUndo, string name) => throw null!;

        public static void RecordObject(Object objectToUndo, string name) => throw null!;
    }
}
