using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// Lazy frames with <c>key_memory</c> on the host: every keys run's output is read back into each request's
    /// <see cref="TransitionRequest.KeyMemory"/>, and the next frames of every playing request with the same number of
    /// past keys are gathered into one batch of the frame graph (rows may differ in gap length and frame), due frames
    /// first, then those ahead of playback.
    /// </summary>
    internal sealed class HostFrameRuns : LazyFrameRuns
    {
        public HostFrameRuns(BatchPump pump)
            : base(pump)
        {
        }

        protected override int RunAllFrames(int tokenBudget, int framesPerRequest, int spent)
        {
            for (int round = 0; round < framesPerRequest; round++)
            {
                int before = spent;
                // Due frames first (decoded ≤ needed), then those ahead of playback.
                for (int urgency = BatchPlanner.Due; urgency <= BatchPlanner.Ahead; urgency++)
                {
                    for (int i = 0; i < Pump.Active.Count; i++)
                    {
                        TransitionRequest request = Pump.Active[i];
                        if (BatchPlanner.FrameUrgency(request) != urgency) continue;
                        BatchBuffers group = Pump.BuffersFor(request.Transition.PastFrames);
                        if (group.FramePending != null) continue;
                        group.Scratch.Add(request);
                    }
                }

                spent = RunGathered(Graph.Frames, tokenBudget, spent);
                if (spent == before) break;
            }

            return spent;
        }

        protected override void ScatterKeys(BatchBuffers group, int rows, IInferenceBinding binding)
        {
            float[] memory = group.Keys!.KeyMemory!.Floats!;
            int size = group.MemorySize;
            for (int r = 0; r < rows; r++)
            {
                TransitionRequest request = group.KeysRequests[r]!;
                group.KeysRequests[r] = null;
                request.InFlight = false;
                if (request.KeyMemory == null || request.KeyMemory.Length != size) request.KeyMemory = new float[size];
                Array.Copy(memory, r * size, request.KeyMemory, 0, size);
                request.Encoded = true;
            }
        }

        protected override int RunFrameBatch(BatchBuffers group, int budget, bool first)
        {
            int per = Pump.FramesPerRun;
            int rows = group.Ensure(BatchPlanner.RowsThatFit(group.Scratch.Count, Pump.MaxBatch, budget, per, first));
            if (rows <= 0) return 0;
            if (rows == group.Scratch.Count) KeepRows(group, rows);
            GraphTensors tensors = group.Frame!;
            float[] memory = tensors.KeyMemory!.Floats!;
            int size = group.MemorySize;
            for (int r = 0; r < rows; r++)
            {
                TransitionRequest request = group.Scratch[r];
                // A row that already holds this request's key encoding (the same requests in the same order as
                // the last run: the steady state of a playing crowd) is not copied again.
                if (!ReferenceEquals(group.RowOwner[r], request) || group.RowGeneration[r] != request.Generation)
                {
                    Array.Copy(request.KeyMemory!, 0, memory, r * size, size);
                    Pump.CountKeyMemoryCopy();
                    group.RowOwner[r] = request;
                    group.RowGeneration[r] = request.Generation;
                }

                request.FrameRow = r;

                int n = request.Transition.MissingFrames;
                int from = request.Decoded;
                tensors.SetKeyRow(r, n);
                // Frames from..from+N−1, the ones past the gap repeated as its last (computed, not used).
                long[] query = tensors.QueryFrameIndices!.Longs!;
                for (int q = 0; q < per; q++) query[r * per + q] = group.Past + Math.Min(from + q, n - 1);
                group.FrameRequests[r] = request;
                group.FrameIndex[r] = from;
            }

            if (Launch(group, Graph.Frames, rows, rows * per, out IInferenceBinding? binding)) ScatterFrames(group, rows);
            return binding == null ? 0 : rows * per;
        }

        /// <summary>
        /// Orders the first <paramref name="rows"/> requests of the group's scratch (all of them: the whole set runs at
        /// once, so their order within the run changes no result) so that each request whose key memory a row of the
        /// frame tensor still holds from the last run keeps that row, and the others take the free rows in their order.
        /// When a transition ends, the requests after it would otherwise each move up a row and have their whole key
        /// memory (R × 2 × K × D floats) copied again; now only the new ones are copied.
        /// </summary>
        private static void KeepRows(BatchBuffers group, int rows)
        {
            List<TransitionRequest> scratch = group.Scratch;
            TransitionRequest?[] placed = group.Placement;
            int homeless = 0;
            for (int i = 0; i < rows; i++)
            {
                TransitionRequest request = scratch[i];
                int row = request.FrameRow;
                if (row >= 0 && row < rows && placed[row] == null && ReferenceEquals(group.RowOwner[row], request) && group.RowGeneration[row] == request.Generation)
                {
                    placed[row] = request;
                }
                else
                {
                    // Read already (homeless ≤ i): the front of the scratch holds the requests without a row, in order.
                    scratch[homeless++] = request;
                }
            }

            int next = 0;
            for (int row = 0; row < rows; row++)
            {
                if (placed[row] == null) placed[row] = scratch[next++];
            }

            for (int row = 0; row < rows; row++)
            {
                scratch[row] = placed[row]!;
                placed[row] = null;
            }
        }

        private void ScatterFrames(BatchBuffers group, int rows)
        {
            for (int r = 0; r < rows; r++)
            {
                TransitionRequest request = group.FrameRequests[r]!;
                group.FrameRequests[r] = null;
                request.InFlight = false;
                if (request.Cancelled) continue;
                Pump.Publish(request, group.Frame!, r, group.FrameIndex[r]);
            }
        }

        protected override void CollectFrames(BatchBuffers group)
        {
            IAsyncInferenceBinding? pending = group.FramePending;
            if (pending == null || !BatchPump.IsOver(pending, group.FrameRequests, group.FramePendingRows, out bool finished)) return;
            group.FramePending = null;
            if (finished) ScatterFrames(group, group.FramePendingRows);
        }
    }
}
