using System;

namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/Attributes.cs
    public sealed partial class RequireComponent : Attribute
    {
        public RequireComponent(Type requiredComponent) => throw null!;
    }
}
