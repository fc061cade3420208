namespace DeltaInterpolator.Core.Inbetweening
{
    /// <summary>
    /// What to feed a model when fewer past frames exist than it wants (the first gap of a baked clip, or
    /// the benchmark's <c>--past-frames P</c> below 10).
    /// </summary>
    /// <remarks>
    /// Measured with the shipped model, which was trained at 10 past frames only, on the official
    /// benchmark windows (L2P ÷ SLERP at n = 5/15/30): 5 frames fed alone 1.06/1.08/1.09, repeated to 10
    /// frames 0.75/0.73/0.75; one frame fed alone 1.11/1.08/1.35, repeated 1.03/1.06/1.04. A model
    /// trained on short contexts (past frames 1..10) should get what exists.
    /// </remarks>
    public enum ShortContextPolicy
    {
        /// <summary>
        /// Feed only the frames that exist, as P past keys with frame indices 0..P−1 (right for a model
        /// whose training range of past frames includes P).
        /// </summary>
        FeedAvailable,

        /// <summary>
        /// Repeat the earliest available frame in front of the available ones until the wanted number of
        /// past keys is reached (right for a model trained at a fixed number of past frames: it sees the
        /// layout it knows, with a character that stood still before the context began).
        /// </summary>
        RepeatEarliest,
    }
}
