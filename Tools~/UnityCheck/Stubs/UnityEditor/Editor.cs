using UnityEngine;
using UnityObject = UnityEngine.Object;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Inspector/Editor.cs
    public partial class Editor : ScriptableObject
    {
        public UnityObject target { get => throw null!; set => throw null!; }

        public virtual void OnInspectorGUI() => throw null!;

        public bool DrawDefaultInspector() => throw null!;
    }
}
