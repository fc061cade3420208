using System;
using DeltaInterpolator.Core;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Presenters
{
    /// <summary>
    /// Progress bars with ETA for a long job, on stderr so that stdout holds only the results. When stderr
    /// is not a terminal (CI logs, pipes) the bars are skipped instead of leaving escape-code residue.
    /// </summary>
    internal static class ProgressBars
    {
        /// <summary>Runs <paramref name="work"/> with a progress receiver (null when bars are skipped).</summary>
        public static void Run(Action<IProgress<StageProgress>?> work)
        {
            IAnsiConsole progressConsole = AnsiConsole.Create(new AnsiConsoleSettings
            {
                Out = new AnsiConsoleOutput(Console.Error),
                Interactive = Console.IsErrorRedirected ? InteractionSupport.No : InteractionSupport.Detect,
            });
            progressConsole.Progress()
                .AutoClear(true)
                .HideCompleted(false)
                .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn(), new RemainingTimeColumn())
                .Start(ctx => work(Console.IsErrorRedirected ? null : new SpectreProgress(ctx)));
        }
    }
}
