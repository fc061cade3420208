using System;

namespace UnityEditor
{
    // source: unity:Editor/Mono/EditorAssemblies.cs
    [AttributeUsage(AttributeTargets.Method)]
    public partial class InitializeOnLoadMethodAttribute : Attribute
    {
    }
}
