namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/TextAsset.cs
    public partial class TextAsset : Object
    {
        public TextAsset(string text) => throw null!;

        public string text => throw null!;
    }
}
