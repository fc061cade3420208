namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>The stages of one scheduler pump, as <see cref="IScheduleTimer"/> reports them.</summary>
    public enum ScheduleStage
    {
        /// <summary>Collecting finished asynchronous runs and scattering their rows.</summary>
        Collect,

        /// <summary>Gathering new requests' keys, running the keys graph, scattering <c>key_memory</c>.</summary>
        Keys,

        /// <summary>Gathering the next frames, running the frame graph, decoding the rows into frames.</summary>
        Frames,

        /// <summary>Whole-transition runs (models without the lazy graphs).</summary>
        Whole,
    }

    /// <summary>
    /// The one timing hook of the schedulers: each stage of a pump is bracketed by <see cref="Begin"/> and
    /// <see cref="End"/> on the thread that pumps. Core stays engine-free; the Unity layer turns the stages into
    /// <c>ProfilerMarker</c>s, a benchmark into clocks. Implementations must not allocate.
    /// </summary>
    public interface IScheduleTimer
    {
        /// <summary>A stage starts.</summary>
        void Begin(ScheduleStage stage);

        /// <summary>The stage started last ends.</summary>
        void End(ScheduleStage stage);
    }
}
