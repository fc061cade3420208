namespace UnityEditor
{
    // source: unity:Editor/Mono/Animation/EditorCurveBinding.bindings.cs
    public partial struct EditorCurveBinding
    {
        public string path;

        public string propertyName;

        public System.Type type { get => throw null!; set => throw null!; }

        public static EditorCurveBinding FloatCurve(string inPath, System.Type inType, string inPropertyName) => throw null!;
    }
}
