using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Evaluation.Benchmark
{
    /// <summary>
    /// How the LaFAN1 benchmark cuts and normalises windows. Defaults are the official test protocol:
    /// windows of 65 frames every 40, 10 past frames, transitions of 5/15/30/45 frames, facing +X at
    /// the last past frame with the hips' local +Y as forward.
    /// </summary>
    public sealed class BenchmarkOptions
    {
        /// <summary>Frames per window (official test set: 65).</summary>
        public int Window { get; set; } = 65;

        /// <summary>Frames between window starts (official test set: 40).</summary>
        public int Offset { get; set; } = 40;

        /// <summary>Number of past key frames (official: 10); the facing frame is the last of them.</summary>
        public int PastFrames { get; set; } = 10;

        /// <summary>
        /// How many of the <see cref="PastFrames"/> context frames the in-betweeners are given: the last
        /// <c>FedPastFrames</c> of them (0, the default, means all). The windows, the facing frame and the
        /// target frame do not change, so the SLERP and zero-velocity rows (which use only the last past
        /// frame and the target) do not change either; a model sees the same transitions with less history.
        /// </summary>
        public int FedPastFrames { get; set; }

        /// <summary>
        /// With <see cref="FedPastFrames"/> below <see cref="PastFrames"/>: feed the fed frames alone as
        /// past keys 0..P−1 (<see cref="ShortContextPolicy.FeedAvailable"/>, the default) or repeat the
        /// earliest of them to fill all <see cref="PastFrames"/> keys (<see cref="ShortContextPolicy.RepeatEarliest"/>).
        /// </summary>
        public ShortContextPolicy ShortContext { get; set; } = ShortContextPolicy.FeedAvailable;

        /// <summary>The number of context frames actually given: <see cref="FedPastFrames"/>, or <see cref="PastFrames"/> when 0.</summary>
        public int EffectivePastFrames => FedPastFrames == 0 ? PastFrames : FedPastFrames;

        /// <summary>Past keys per transition: <see cref="PastContext.PastFrames"/> of the fed frames under <see cref="ShortContext"/>.</summary>
        public int TransitionPastFrames => PastContext.PastFrames(EffectivePastFrames, PastFrames, ShortContext);

        /// <summary>Transition lengths n to evaluate (official: 5, 15, 30, 45).</summary>
        public IReadOnlyList<int> Lengths { get; set; } = new[] { 5, 15, 30, 45 };

        /// <summary>The root's local forward axis (LaFAN1 hips: +Y).</summary>
        public Vector3D LocalForwardAxis { get; set; } = Vector3D.UnitY;

        /// <summary>The world axis the root faces after normalisation (official: +X).</summary>
        public Vector3D TargetAxis { get; set; } = Vector3D.UnitX;

        /// <summary>
        /// Checks the options and says what to change. Every transition must fit in a window:
        /// P past frames + n missing + 1 target ≤ window.
        /// </summary>
        /// <exception cref="ArgumentException">An option is out of range.</exception>
        public void Validate()
        {
            if (PastFrames < 1) throw new ArgumentException($"past frames = {PastFrames}; expected at least 1");
            if (FedPastFrames < 0 || FedPastFrames > PastFrames)
            {
                throw new ArgumentException($"past frames fed = {FedPastFrames}; expected 1..{PastFrames} (the last P of the {PastFrames} context frames)");
            }

            if (Offset < 1) throw new ArgumentException($"offset = {Offset}; expected at least 1 frame between windows");
            if (Lengths == null || Lengths.Count == 0) throw new ArgumentException("no transition lengths; expected at least one, e.g. 5,15,30,45");
            var seen = new HashSet<int>();
            foreach (int n in Lengths)
            {
                if (n < 1) throw new ArgumentException($"transition length {n}; expected at least 1 missing frame");
                if (!seen.Add(n)) throw new ArgumentException($"transition length {n} is listed twice; expected each length once");
                if (PastFrames + n + 1 > Window)
                {
                    throw new ArgumentException($"window is {Window} frames but transition length {n} needs {PastFrames + n + 1} ({PastFrames} past + {n} missing + 1 target); expected a longer window or shorter transitions");
                }
            }
        }
    }
}
