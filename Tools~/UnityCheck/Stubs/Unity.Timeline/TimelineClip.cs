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

        // Timeline 1.8.10 Runtime/TimelineClip.cs:446-457 (the blend-in or ease-in weight curve; a broken one is reset to the default)
        public AnimationCurve mixInCurve { get => throw null!; set => throw null!; }

        // Timeline 1.8.10 Runtime/TimelineClip.cs:55-81 (the enum), 677-690 (the modes; their setters are internal)
        public enum ClipExtrapolation
        {
            None = 0,
            Hold = 1,
            Loop = 2,
            PingPong = 3,
            Continue = 4,
        }

        public ClipExtrapolation postExtrapolationMode => throw null!;

        public ClipExtrapolation preExtrapolationMode => throw null!;
    }
}
