namespace UnityEditor
{
    // source: unity:Editor/Mono/Animation/EditorCurveBinding.bindings.cs
    public partial struct EditorCurveBinding
    {
        public string propertyName;

        public static EditorCurveBinding FloatCurve(string inPath, System.Type inType, string inPropertyName) => throw null!;
    }
}
