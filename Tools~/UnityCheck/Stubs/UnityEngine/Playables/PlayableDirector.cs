namespace UnityEngine.Playables
{
    // source: unity:Modules/Director/ScriptBindings/PlayableDirector.bindings.cs
    public partial class PlayableDirector : Behaviour
    {
        public PlayableAsset playableAsset { get => throw null!; set => throw null!; }

        public double time { get => throw null!; set => throw null!; }

        public Object GetGenericBinding(Object key) => throw null!;

        public void SetGenericBinding(Object key, Object value) => throw null!;
    }
}
