using System;

namespace UnityEditor
{
    // source: unity:Editor/Mono/Inspector/Core/CustomEditor.cs
    public partial class CustomEditor : Attribute
    {
        public CustomEditor(Type inspectedType) => throw null!;
    }
}
