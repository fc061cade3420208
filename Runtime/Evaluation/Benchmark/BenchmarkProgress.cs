namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>Progress of a long benchmark step, for progress bars.</summary>
    public readonly struct BenchmarkProgress
    {
        /// <summary>Creates a progress report.</summary>
        public BenchmarkProgress(string stage, int completed, int total)
        {
            Stage = stage;
            Completed = completed;
            Total = total;
        }

        /// <summary>What is being done, e.g. "Reading test files" or "Evaluating windows".</summary>
        public string Stage { get; }

        /// <summary>Units done so far.</summary>
        public int Completed { get; }

        /// <summary>Units in the stage.</summary>
        public int Total { get; }
    }
}
