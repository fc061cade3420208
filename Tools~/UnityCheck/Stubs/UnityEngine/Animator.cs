namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/Animator.bindings.cs
    public partial class Animator : Behaviour
    {
    }
}
