using System.Collections.Generic;

namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>What <see cref="RuntimeSpeed.Measure"/> found: one timing per measurement and transition length.</summary>
    public sealed class SpeedResults
    {
        internal SpeedResults(Timing[] transition, Timing[] network, Timing? lazyKeys, Timing? lazyFrame, Timing slerpFk, double allocatedBytesPerTransition)
        {
            Transition = transition;
            Network = network;
            LazyKeys = lazyKeys;
            LazyFrame = lazyFrame;
            SlerpFk = slerpFk;
            AllocatedBytesPerTransition = allocatedBytesPerTransition;
        }

        /// <summary>The whole pipeline per request (ms), parallel to <see cref="RuntimeSpeed.Lengths"/>.</summary>
        public IReadOnlyList<Timing> Transition { get; }

        /// <summary>The network run alone (ms), parallel to <see cref="RuntimeSpeed.Lengths"/>.</summary>
        public IReadOnlyList<Timing> Network { get; }

        /// <summary>Encoding the keys for lazy decoding (ms, <see cref="RuntimeSpeed.LazyLength"/> missing frames); null without the lazy graphs.</summary>
        public Timing? LazyKeys { get; }

        /// <summary>One frame decoded lazily after the keys (ms); null without the lazy graphs.</summary>
        public Timing? LazyFrame { get; }

        /// <summary>
        /// One lazily decoded frame as a fraction of a whole transition of <see cref="RuntimeSpeed.LazyLength"/>
        /// frames (medians): what spreading the decoding over rendered frames saves per frame.
        /// </summary>
        public double? LazyFrameFraction => LazyFrame == null ? (double?)null : LazyFrame.Value.Median / TransitionAt(RuntimeSpeed.LazyLength).Median;

        /// <summary>The SLERP baseline and forward kinematics alone (µs, <see cref="RuntimeSpeed.LazyLength"/> frames).</summary>
        public Timing SlerpFk { get; }

        /// <summary>Managed bytes allocated per transition in steady state (0 is the goal of the hot path).</summary>
        public double AllocatedBytesPerTransition { get; }

        /// <summary>The whole-pipeline timing at transition length <paramref name="missingFrames"/>.</summary>
        public Timing TransitionAt(int missingFrames) => Transition[RuntimeSpeed.IndexOf(missingFrames)];

        /// <summary>How many times faster this runtime is than <paramref name="otherMedianMs"/> at a length (medians).</summary>
        public double SpeedupOver(double otherMedianMs, int missingFrames) => otherMedianMs / TransitionAt(missingFrames).Median;
    }
}
