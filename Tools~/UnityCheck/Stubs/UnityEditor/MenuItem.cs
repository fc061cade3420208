using System;

namespace UnityEditor
{
    // source: unity:Editor/Mono/MenuItem.cs
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed partial class MenuItem : Attribute
    {
        public MenuItem(string itemName) => throw null!;
    }
}
