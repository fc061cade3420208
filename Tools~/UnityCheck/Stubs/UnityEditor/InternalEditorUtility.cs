namespace UnityEditorInternal
{
    // source: unity:Editor/Mono/InternalEditorUtility.bindings.cs
    public partial class InternalEditorUtility
    {
        public static void RepaintAllViews() => throw null!;
    }
}
