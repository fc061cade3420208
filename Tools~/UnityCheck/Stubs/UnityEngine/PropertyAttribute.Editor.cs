using System;

namespace UnityEngine
{
    // source: unity:Runtime/Export/PropertyDrawer/PropertyAttribute.cs
    public abstract partial class PropertyAttribute : Attribute
    {
    }
}
