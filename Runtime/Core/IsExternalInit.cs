namespace System.Runtime.CompilerServices
{
    /// <summary>
    /// The marker of init-only setters, which C# 9 records declare. .NET 5 and later define it; .NET Standard 2.1, which
    /// Unity compiles this assembly against, does not, so each of our assemblies that declares a record carries its own, as
    /// Unity's manual says (https://docs.unity3d.com/2022.3/Documentation/Manual/CSharpCompiler.html, "Record support").
    /// Internal, so it never clashes with another assembly's or the runtime's.
    /// </summary>
    internal static class IsExternalInit
    {
    }
}
