using System;
using DeltaInterpolator.Core.Inbetweening;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// How a <see cref="BatchPump"/> turns requests into network runs: whole transitions
    /// (<see cref="WholeTransitionRuns"/>), frames decoded lazily with <c>key_memory</c> on the host
    /// (<see cref="HostFrameRuns"/>) or kept on the engine's device (<see cref="DeviceFrameRuns"/>). One pump has
    /// one strategy, chosen at creation from the model's graphs and backends.
    /// </summary>
    internal abstract class RunStrategy
    {
        protected RunStrategy(BatchPump pump)
        {
            Pump = pump;
        }

        protected BatchPump Pump { get; }

        /// <summary>Collects the finished asynchronous runs of one set of batch buffers and scatters their rows.</summary>
        public virtual void Collect(BatchBuffers buffers)
        {
        }

        /// <summary>Releases what no playing request needs any more (device tensors).</summary>
        public virtual void Release()
        {
        }

        /// <summary>Schedules this pump's runs within <paramref name="tokenBudget"/>; returns the tokens scheduled.</summary>
        public abstract int Run(int tokenBudget, int framesPerRequest);
    }

    /// <summary>One run per request of the whole-transition graph (models loaded without the lazy graphs).</summary>
    internal sealed class WholeTransitionRuns : RunStrategy
    {
        public WholeTransitionRuns(BatchPump pump)
            : base(pump)
        {
        }

        public override int Run(int tokenBudget, int framesPerRequest)
        {
            Pump.Timer?.Begin(ScheduleStage.Whole);
            int spent = 0;
            for (int i = 0; i < Pump.Active.Count; i++)
            {
                TransitionRequest request = Pump.Active[i];
                if (!BatchPlanner.WantsWholeRun(request)) continue;
                Transition t = request.Transition;
                int cost = BatchPlanner.WholeRunCost(t);
                if (!BatchPlanner.Fits(spent, cost, tokenBudget)) break;
                try
                {
                    Pump.Model.Inbetween(t);
                    request.Publish(t.MissingFrames);
                }
                catch (Exception e)
                {
                    request.Error = e;
                }

                spent += cost;
                Pump.Count(1, cost);
            }

            Pump.Timer?.End(ScheduleStage.Whole);
            return spent;
        }
    }
}
