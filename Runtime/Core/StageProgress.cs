namespace DeltaInterpolator.Core
{
    /// <summary>
    /// Progress of a long job's current stage, for progress bars: what is being done and how many of its units
    /// are done. Bakes report it per gap filled (the stage is the method filling gaps now, the counts run over
    /// every method's gaps); the benchmark per file read and window evaluated.
    /// </summary>
    public readonly struct StageProgress
    {
        /// <summary>Creates a progress report.</summary>
        public StageProgress(string stage, int completed, int total)
        {
            Stage = stage;
            Completed = completed;
            Total = total;
        }

        /// <summary>What is being done, e.g. "Reading test files", "Evaluating windows", or a bake's method name.</summary>
        public string Stage { get; }

        /// <summary>Units done so far.</summary>
        public int Completed { get; }

        /// <summary>Units in the stage.</summary>
        public int Total { get; }
    }
}
