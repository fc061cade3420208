namespace UnityEngine
{
    // source: unity:Modules/Animation/ScriptBindings/HumanTrait.bindings.cs
    public partial class HumanTrait
    {
        public static int MuscleCount => throw null!;

        public static string[] MuscleName => throw null!;
    }
}
