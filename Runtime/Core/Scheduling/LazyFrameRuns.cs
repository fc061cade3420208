using System;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// The lazy strategies' common half: the keys of new requests, oldest first, run as one batch of the keys graph per
    /// number of past keys (K = P + 1 tokens a row); where their <c>key_memory</c> goes and how frames run is the
    /// subclass's (<see cref="HostFrameRuns"/>, <see cref="DeviceFrameRuns"/>).
    /// </summary>
    internal abstract class LazyFrameRuns : RunStrategy
    {
        protected LazyFrameRuns(BatchPump pump)
            : base(pump)
        {
        }

        public sealed override void Collect(BatchBuffers buffers)
        {
            CollectKeys(buffers);
            CollectFrames(buffers);
        }

        /// <summary>All keys runs first (a frame run needs its rows' <c>key_memory</c>), then the subclass's frame runs.</summary>
        public sealed override int Run(int tokenBudget, int framesPerRequest)
        {
            int spent = RunAllKeys(tokenBudget);
            Pump.Timer?.Begin(ScheduleStage.Frames);
            spent = RunAllFrames(tokenBudget, framesPerRequest, spent);
            Pump.Timer?.End(ScheduleStage.Frames);
            return spent;
        }

        /// <summary>Frame runs within what is left of the budget after <paramref name="spent"/>; returns the tokens spent in all.</summary>
        protected abstract int RunAllFrames(int tokenBudget, int framesPerRequest, int spent);

        /// <summary>Completes this group's scheduled frame runs that are over.</summary>
        protected abstract void CollectFrames(BatchBuffers group);

        /// <summary>Which of a group's two graphs a batch runs: the keys graph or the frame graph.</summary>
        protected enum Graph
        {
            Keys,
            Frames,
        }

        /// <summary>
        /// Binds the batch of <paramref name="rows"/> gathered for <paramref name="graph"/> and runs it, or schedules it
        /// (then the group holds it as pending); true where it ran to the end here, so its output is scattered now. A
        /// binding that fails fails the rows and leaves <paramref name="binding"/> null (nothing was spent).
        /// </summary>
        protected bool Launch(BatchBuffers group, Graph graph, int rows, int tokens, out IInferenceBinding? binding)
        {
            bool keys = graph == Graph.Keys;
            TransitionRequest?[] requests = keys ? group.KeysRequests : group.FrameRequests;
            try
            {
                binding = keys ? group.KeysBinding(rows, Pump.Model.KeysBackend!) : group.FrameBinding(rows, Pump.Model.FrameBackend!);
            }
            catch (Exception e)
            {
                BatchPump.Fail(requests, rows, e);
                binding = null;
                return false;
            }

            if (Pump.RunOrSchedule(binding, requests, rows, tokens, out IAsyncInferenceBinding? pending)) return true;
            if (pending == null) return false;
            if (keys)
            {
                group.KeysPending = pending;
                group.KeysPendingRows = rows;
            }
            else
            {
                group.FramePending = pending;
                group.FramePendingRows = rows;
            }

            return false;
        }

        /// <summary>
        /// Runs the requests gathered in each group's <see cref="BatchBuffers.Scratch"/> as batches of
        /// <paramref name="graph"/>, one run per MaxBatch rows (all of them in one run when batched), while the budget
        /// lasts and the group has no run of that graph pending; empties every scratch; returns the tokens spent in all.
        /// </summary>
        protected int RunGathered(Graph graph, int tokenBudget, int spent)
        {
            bool keys = graph == Graph.Keys;
            for (int g = 0; g < Pump.Buffers.Count; g++)
            {
                BatchBuffers group = Pump.Buffers[g];
                int perRow = keys ? group.Past + 1 : Pump.FramesPerRun;
                while (group.Scratch.Count > 0 && (keys ? group.KeysPending : group.FramePending) == null)
                {
                    int budget = tokenBudget - spent;
                    int used = keys ? RunKeys(group, budget, spent == 0) : RunFrameBatch(group, budget, spent == 0);
                    if (used == 0) break;
                    spent += used;
                    group.Scratch.RemoveRange(0, Math.Min(group.Scratch.Count, used / perRow));
                }

                group.Scratch.Clear();
            }

            return spent;
        }

        /// <summary>
        /// One frame run of the first rows of a group's scratch, within <paramref name="budget"/>; returns the tokens
        /// spent. Only a strategy that gathers frames per group (<see cref="HostFrameRuns"/>) runs them so; one that
        /// batches frames per keys run (<see cref="DeviceFrameRuns"/>) never gathers any, and this spends nothing.
        /// </summary>
        protected virtual int RunFrameBatch(BatchBuffers group, int budget, bool first) => 0;

        /// <summary>Keys runs of every request waiting for its keys, within the budget; returns the tokens spent.</summary>
        private int RunAllKeys(int tokenBudget)
        {
            Pump.Timer?.Begin(ScheduleStage.Keys);
            int spent = 0;
            for (int i = 0; i < Pump.Active.Count; i++)
            {
                TransitionRequest request = Pump.Active[i];
                if (!BatchPlanner.WantsKeys(request)) continue;
                BatchBuffers group = Pump.BuffersFor(request.Transition.PastFrames);
                if (group.KeysPending != null) continue;
                group.Scratch.Add(request);
            }

            spent = RunGathered(Graph.Keys, tokenBudget, spent);
            Pump.Timer?.End(ScheduleStage.Keys);
            return spent;
        }

        /// <summary>Where a finished keys run's <c>key_memory</c> goes (read back to the host, or kept on the device).</summary>
        protected abstract void ScatterKeys(BatchBuffers group, int rows, IInferenceBinding binding);

        private void CollectKeys(BatchBuffers group)
        {
            IAsyncInferenceBinding? pending = group.KeysPending;
            if (pending == null || !BatchPump.IsOver(pending, group.KeysRequests, group.KeysPendingRows, out bool finished)) return;
            group.KeysPending = null;
            if (finished) ScatterKeys(group, group.KeysPendingRows, pending);
        }

        private int RunKeys(BatchBuffers group, int budget, bool first)
        {
            int k = group.Past + 1;
            int rows = group.Ensure(BatchPlanner.RowsThatFit(group.Scratch.Count, Pump.MaxBatch, budget, k, first));
            if (rows <= 0) return 0;
            GraphTensors tensors = group.Keys!;
            float[] features = tensors.KeyFeatures!.Floats!;
            int width = k * Pump.Contract.KeyFeatureSize;
            for (int r = 0; r < rows; r++)
            {
                TransitionRequest request = group.Scratch[r];
                Array.Copy(request.KeyFeatures, 0, features, r * width, width);
                tensors.SetKeyRow(r, request.Transition.MissingFrames);
                group.KeysRequests[r] = request;
            }

            if (Launch(group, Graph.Keys, rows, rows * k, out IInferenceBinding? binding)) ScatterKeys(group, rows, binding!);
            return binding == null ? 0 : rows * k;
        }
    }
}
