namespace UnityEngine.Timeline
{
    // source: timeline:Runtime/TimelineClip.cs
    public partial class TimelineClip
    {
        public double timeScale { get => throw null!; set => throw null!; }

        public double start { get => throw null!; set => throw null!; }

        public double duration { get => throw null!; set => throw null!; }

        public double clipIn { get => throw null!; set => throw null!; }

        public string displayName { get => throw null!; set => throw null!; }

        public Object asset { get => throw null!; set => throw null!; }
    }
}
