namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>What <see cref="CrowdBenchmark.Run"/> found for one crowd.</summary>
    public sealed class CrowdTimings
    {
        /// <summary>Characters in the crowd.</summary>
        public int Characters { get; internal set; }

        /// <summary>Rendered frames, over all characters, that held a pose because its model frame was not there (real clock, worker thread).</summary>
        public int FrozenFrames { get; internal set; }

        /// <summary>Model frames, over all characters, that arrived after playback needed them (real clock, worker thread).</summary>
        public int FramesLate { get; internal set; }

        /// <summary>The main thread's cost of all the requests of one rendered frame (ms, rounded to 4 decimals).</summary>
        public double RequestMainThreadMs { get; internal set; }

        /// <summary>Wall time until every character has its first model frame, decoding as fast as it can (ms, 3 decimals).</summary>
        public double AllFirstFramesMs { get; internal set; }

        /// <summary>Wall time until every character has all of its model frames (ms, 3 decimals).</summary>
        public double AllFramesMs { get; internal set; }

        /// <summary>Inference per rendered frame while all play, batched: the scheduler's gathering, graph runs and scattering (ms, 4 decimals).</summary>
        public double FrameMsBatched { get; internal set; }

        /// <summary>Inference per rendered frame while all play, one run per character (ms, 4 decimals).</summary>
        public double FrameMsUnbatched { get; internal set; }

        /// <summary>The whole rendered frame while all play, batched: inference and every player's playback (ms, 4 decimals).</summary>
        public double StepMsBatched { get; internal set; }

        /// <summary>The whole rendered frame while all play, one run per character (ms, 4 decimals).</summary>
        public double StepMsUnbatched { get; internal set; }
    }
}
