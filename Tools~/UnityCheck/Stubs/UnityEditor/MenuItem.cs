using System;

namespace UnityEditor
{
    // source: unity:Editor/Mono/MenuItem.cs
    public sealed partial class MenuItem : Attribute
    {
        public MenuItem(string itemName) => throw null!;
    }
}
