using System;

namespace UnityEngine
{
    // source: unity:Runtime/Export/PropertyDrawer/PropertyAttribute.cs
    public partial class TooltipAttribute : PropertyAttribute
    {
        public TooltipAttribute(string tooltip) => throw null!;
    }
}
