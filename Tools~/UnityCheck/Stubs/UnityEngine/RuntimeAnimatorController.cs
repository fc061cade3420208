namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/RuntimeAnimatorController.bindings.cs
    public partial class RuntimeAnimatorController : Object
    {
    }
}
