namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/Behaviour.bindings.cs
    public partial class Behaviour : Component
    {
    }
}
