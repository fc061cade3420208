namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/Motion.bindings.cs
    public partial class Motion : Object
    {
        public bool isLooping => throw null!;
    }
}
