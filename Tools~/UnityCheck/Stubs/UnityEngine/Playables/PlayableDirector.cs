namespace UnityEngine.Playables
{
    // source: unity:Modules/Director/ScriptBindings/PlayableDirector.bindings.cs
    public partial class PlayableDirector : Behaviour
    {
        public PlayableAsset playableAsset { get => throw null!; set => throw null!; }

        public double time { get => throw null!; set => throw null!; }

        public Object GetGenericBinding(Object key) => throw null!;

        // UnityCsReference 6000.0 Modules/Director/ScriptBindings/PlayableDirector.bindings.cs:88-89 (builds the graph if needed and plays it)
        public void Play() => throw null!;

        public void SetGenericBinding(Object key, Object value) => throw null!;
    }
}
