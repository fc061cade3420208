using System;
using UnityEngine;
using Object = UnityEngine.Object;
using UnityObject = UnityEngine.Object;

namespace UnityEditor
{
    // source: unity:Editor/Mono/SerializedObject.bindings.cs
    public partial class SerializedObject : IDisposable
    {
        public SerializedObject(Object obj) => throw null!;

        public SerializedProperty FindProperty(string propertyPath) => throw null!;

        public bool ApplyModifiedPropertiesWithoutUndo() => throw null!;

        public void Dispose() => throw null!;
    }

    // source: unity:Editor/Mono/SerializedProperty.bindings.cs
    public partial class SerializedProperty : IDisposable
    {
        public UnityObject objectReferenceValue { get => throw null!; set => throw null!; }

        public int enumValueIndex { get => throw null!; set => throw null!; }

        public float floatValue { get => throw null!; set => throw null!; }

        public string stringValue { get => throw null!; set => throw null!; }

        public void Dispose() => throw null!;
    }
}
