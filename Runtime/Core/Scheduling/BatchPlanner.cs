using System;
using DeltaInterpolator.Core.Inbetweening;

namespace DeltaInterpolator.Core.Scheduling
{
    /// <summary>
    /// Which rows run this pump, as pure rules over requests and numbers (no engine, no buffers): a request's keys
    /// run once; its frames are due (playback needs them now: <see cref="TransitionRequest.Needed"/> reached) or
    /// ahead of playback, due first; a run takes as many rows as the batch and the token budget allow (a keys row
    /// costs K = P + 1 tokens, a frame row the frames it decodes), and the first run of a pump always runs, so work
    /// progresses under any budget.
    /// </summary>
    internal static class BatchPlanner
    {
        /// <summary>No frame of the request is wanted from a run now.</summary>
        public const int NotWanted = 0;

        /// <summary>Playback needs the request's next frame already (decoded ≤ needed).</summary>
        public const int Due = 1;

        /// <summary>The request plays and its next frame is ahead of playback.</summary>
        public const int Ahead = 2;

        /// <summary>True while the request's keys wait for a keys run.</summary>
        public static bool WantsKeys(TransitionRequest request) => !request.Encoded && !request.InFlight && !request.Cancelled;

        /// <summary>True when a whole-transition run should decode the request (nothing decoded yet).</summary>
        public static bool WantsWholeRun(TransitionRequest request) => !request.Cancelled && request.Decoded == 0 && request.Error == null;

        /// <summary>The tokens a whole-transition run of <paramref name="transition"/> costs: K + n.</summary>
        public static int WholeRunCost(Transition transition) => transition.KeyFrameCount + transition.MissingFrames;

        /// <summary><see cref="NotWanted"/>, <see cref="Due"/> or <see cref="Ahead"/> for a request's next frame run.</summary>
        public static int FrameUrgency(TransitionRequest request)
        {
            if (!request.Encoded || request.InFlight || request.Cancelled || request.Error != null) return NotWanted;
            int decoded = request.Decoded;
            if (decoded >= request.Transition.MissingFrames) return NotWanted;
            return decoded <= request.Needed ? Due : Ahead;
        }

        /// <summary>True when the scheduler is done with the request (retired: finished, and reusable by its player).</summary>
        public static bool IsDone(TransitionRequest request) =>
            !request.InFlight && (request.Cancelled || request.Error != null || request.Decoded >= request.Transition.MissingFrames);

        /// <summary>
        /// Rows of one run: the waiting rows up to <paramref name="maxBatch"/>, as many as <paramref name="budget"/>
        /// tokens pay for at <paramref name="costPerRow"/> each (at least one for the <paramref name="first"/> run of a pump).
        /// </summary>
        public static int RowsThatFit(int waiting, int maxBatch, int budget, int costPerRow, bool first)
        {
            int rows = Math.Min(waiting, maxBatch);
            int fit = Math.Max(0, budget) / costPerRow;
            if (rows > fit) rows = first ? Math.Max(1, fit) : fit;
            return rows;
        }

        /// <summary>True when a run of <paramref name="cost"/> tokens fits after <paramref name="spent"/> (the first always does).</summary>
        public static bool Fits(int spent, int cost, int budget) => spent == 0 || spent + cost <= budget;
    }
}
