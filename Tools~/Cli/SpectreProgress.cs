using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using Spectre.Console;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// Shows Core's <see cref="StageProgress"/> reports as Spectre.Console progress bars, one bar per
    /// stage. Reports may come from worker threads (parallel file reading), so access is locked; unlike
    /// <see cref="Progress{T}"/> it updates synchronously.
    /// </summary>
    public sealed class SpectreProgress : IProgress<StageProgress>
    {
        private readonly ProgressContext _context;
        private readonly Dictionary<string, ProgressTask> _tasks = new Dictionary<string, ProgressTask>();
        private readonly object _gate = new object();

        public SpectreProgress(ProgressContext context)
        {
            _context = context;
        }

        /// <inheritdoc />
        public void Report(StageProgress value)
        {
            lock (_gate)
            {
                if (!_tasks.TryGetValue(value.Stage, out ProgressTask? task))
                {
                    task = _context.AddTask(Markup.Escape(value.Stage), true, Math.Max(1, value.Total));
                    _tasks.Add(value.Stage, task);
                }

                task.MaxValue = Math.Max(1, value.Total);
                task.Value = Math.Max(task.Value, value.Completed);
            }
        }
    }
}
