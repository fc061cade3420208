using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// Lazy frames with <c>key_memory</c> kept on the engine's device (both lazy graphs' backends are
    /// <see cref="IDeviceTensorBackend"/>s: Sentis on a GPU): each keys run's output stays there, held by a
    /// <see cref="DeviceRun"/> until none of its rows plays any more, and frames are batched per keys run: every frame
    /// run binds one keys run's device tensor and decodes all of its rows (a finished or superseded row's frames are
    /// computed and ignored), so no gather on the device is needed.
    /// </summary>
    internal sealed class DeviceFrameRuns : LazyFrameRuns
    {
        private readonly List<DeviceRun> _runScratch = new List<DeviceRun>(64);

        public DeviceFrameRuns(BatchPump pump)
            : base(pump)
        {
        }

        /// <summary>A finished keys run on a device backend: its <c>key_memory</c> stays there, held by a <see cref="DeviceRun"/> of its rows.</summary>
        protected override void ScatterKeys(BatchBuffers group, int rows, IInferenceBinding keysBinding)
        {
            IDeviceTensor memory;
            try
            {
                memory = ((IDeviceTensorBinding)keysBinding).TakeOutput();
            }
            catch (Exception e)
            {
                BatchPump.Fail(group.KeysRequests, rows, e);
                return;
            }

            DeviceRun run = group.Rent(rows);
            run.Memory = memory;
            for (int r = 0; r < rows; r++)
            {
                TransitionRequest request = group.KeysRequests[r]!;
                group.KeysRequests[r] = null;
                request.InFlight = false;
                run.Hold(r, request);
                request.Encoded = true;
            }
        }

        /// <summary>
        /// Frame runs of the keys runs held on the device, one per keys run with rows still playing (those whose
        /// frames are due first, then those ahead of playback, each in request order), within the budget (a run
        /// costs all of its rows).
        /// </summary>
        protected override int RunAllFrames(int tokenBudget, int framesPerRequest, int spent)
        {
            for (int round = 0; round < framesPerRequest; round++)
            {
                int before = spent;
                _runScratch.Clear();
                for (int urgency = BatchPlanner.Due; urgency <= BatchPlanner.Ahead; urgency++)
                {
                    for (int g = 0; g < Pump.Buffers.Count; g++)
                    {
                        List<DeviceRun> runs = Pump.Buffers[g].Runs;
                        for (int i = 0; i < runs.Count; i++)
                        {
                            if (runs[i].Pending == null && runs[i].Urgency() == urgency) _runScratch.Add(runs[i]);
                        }
                    }
                }

                for (int i = 0; i < _runScratch.Count; i++)
                {
                    DeviceRun run = _runScratch[i];
                    int cost = run.Rows * Pump.FramesPerRun;
                    if (!BatchPlanner.Fits(spent, cost, tokenBudget)) continue;
                    spent += RunFrame(run);
                }

                _runScratch.Clear();
                if (spent == before) break;
            }

            return spent;
        }

        private int RunFrame(DeviceRun run)
        {
            int per = Pump.FramesPerRun;
            int rows = run.Rows;
            GraphTensors tensors = run.Frame;
            long[] query = tensors.QueryFrameIndices!.Longs!;
            long[] missing = tensors.GapLength.Longs!;   // n per row (the contract's gap_length input)
            int past = tensors.PastFrames;
            for (int r = 0; r < rows; r++)
            {
                int n = (int)missing[r];
                // A row that no longer plays asks for its last frame again (computed, not used).
                int from = run.Live(r) ? run.Requests[r]!.Decoded : -1;
                run.FrameIndex[r] = from;
                int first = from < 0 ? n - 1 : from;
                for (int q = 0; q < per; q++) query[r * per + q] = past + Math.Min(first + q, n - 1);
            }

            IDeviceTensorBinding binding;
            try
            {
                binding = run.Binding(rows, (IDeviceTensorBackend)Pump.Model.FrameBackend!);
                binding.SetInput(run.Memory!);
            }
            catch (Exception e)
            {
                FailRun(run, e);
                return 0;
            }

            Pump.Count(rows, rows * per);
            if (Pump.Async && binding is IAsyncInferenceBinding scheduled)
            {
                for (int r = 0; r < rows; r++)
                {
                    if (run.FrameIndex[r] >= 0) run.Requests[r]!.InFlight = true;
                }

                try
                {
                    scheduled.Schedule();
                }
                catch (Exception e)
                {
                    FailRun(run, e);
                    return rows * per;
                }

                run.Pending = scheduled;
                return rows * per;
            }

            try
            {
                binding.Run();
            }
            catch (Exception e)
            {
                FailRun(run, e);
                return rows * per;
            }

            ScatterRun(run);
            return rows * per;
        }

        private void ScatterRun(DeviceRun run)
        {
            for (int r = 0; r < run.Rows; r++)
            {
                int from = run.FrameIndex[r];
                if (from < 0) continue;
                run.FrameIndex[r] = -1;
                TransitionRequest request = run.Requests[r]!;
                request.InFlight = false;
                if (request.Cancelled) continue;
                Pump.Publish(request, run.Frame, r, from);
            }
        }

        private static void FailRun(DeviceRun run, Exception e)
        {
            for (int r = 0; r < run.Rows; r++)
            {
                if (run.FrameIndex[r] < 0) continue;
                run.FrameIndex[r] = -1;
                TransitionRequest request = run.Requests[r]!;
                request.InFlight = false;
                request.Error = e;
            }
        }

        /// <summary>Releases the device <c>key_memory</c> of every keys run none of whose rows plays any more.</summary>
        public override void Release()
        {
            for (int g = 0; g < Pump.Buffers.Count; g++)
            {
                BatchBuffers group = Pump.Buffers[g];
                for (int i = group.Runs.Count - 1; i >= 0; i--)
                {
                    DeviceRun run = group.Runs[i];
                    if (run.Pending == null && run.Urgency() == 0) group.Release(i);
                }
            }
        }

        protected override void CollectFrames(BatchBuffers group)
        {
            for (int i = 0; i < group.Runs.Count; i++)
            {
                DeviceRun run = group.Runs[i];
                if (run.Pending == null) continue;
                bool done;
                try
                {
                    done = run.Pending.TryComplete();
                }
                catch (Exception e)
                {
                    run.Pending = null;
                    FailRun(run, e);
                    continue;
                }

                if (done)
                {
                    run.Pending = null;
                    ScatterRun(run);
                }
            }
        }
    }
}
