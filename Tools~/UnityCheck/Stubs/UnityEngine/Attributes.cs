using System;

namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/Attributes.cs
    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public sealed partial class DisallowMultipleComponent : Attribute
    {
    }

    // source: unity:Runtime/Export/Scripting/Attributes.cs
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed partial class RequireComponent : Attribute
    {
        public RequireComponent(Type requiredComponent) => throw null!;
    }

    // source: unity:Runtime/Export/Scripting/Attributes.cs
    public sealed partial class AddComponentMenu : Attribute
    {
        public AddComponentMenu(string menuName) => throw null!;
    }

    // source: unity:Runtime/Export/Scripting/Attributes.cs
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = false, Inherited = false)]
    public sealed partial class CreateAssetMenuAttribute : Attribute
    {
        public string menuName { get => throw null!; set => throw null!; }

        public string fileName { get => throw null!; set => throw null!; }

        public int order { get => throw null!; set => throw null!; }
    }

    // source: unity:Runtime/Export/Serialization/Serialization.cs
    public sealed partial class SerializeField : Attribute
    {
    }

    // source: unity:Runtime/Export/PropertyDrawer/PropertyAttribute.cs
    [AttributeUsage(AttributeTargets.Field | AttributeTargets.Property, Inherited = true, AllowMultiple = false)]
    public abstract partial class PropertyAttribute : Attribute
    {
    }

    // source: unity:Runtime/Export/PropertyDrawer/PropertyAttribute.cs
    [AttributeUsage(AttributeTargets.All, Inherited = true, AllowMultiple = false)]
    public partial class TooltipAttribute : PropertyAttribute
    {
        public TooltipAttribute(string tooltip) => throw null!;
    }

    // source: unity:Runtime/Export/Scripting/Attributes.cs
    [AttributeUsage(AttributeTargets.Class)]
    public partial class DefaultExecutionOrder : Attribute
    {
        public DefaultExecutionOrder(int order) => throw null!;

        public int order => throw null!;
    }
}
