using UnityEngine;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Selection/Selection.bindings.cs
    public sealed partial class Selection
    {
        public static GameObject activeGameObject { get => throw null!; set => throw null!; }
    }
}
