namespace UnityEngine
{
    // Messages (Update, OnEnable, ...) are declared nowhere: the engine calls them by name.
    // source: unity:Runtime/Export/Scripting/MonoBehaviour.bindings.cs
    public partial class MonoBehaviour : Behaviour
    {
    }
}
