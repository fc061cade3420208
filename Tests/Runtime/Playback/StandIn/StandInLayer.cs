using System;
using DeltaInterpolator.Core.Playback;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// One layer of the stand-in controller: a state machine that plays a state, crossfades into another over a duration (its
    /// weight rising linearly, as Unity's transitions do) and can be interrupted by a new crossfade, which starts from the state
    /// it was going to (the stand-in drops the old source). A masked layer drives only its mask's bones.
    /// </summary>
    public sealed class StandInLayer
    {
        private readonly double[] _scratch;

        /// <summary>Creates layer <paramref name="index"/> playing <paramref name="initial"/> from its start; <paramref name="mask"/>: the bones it drives (null: all).</summary>
        public StandInLayer(int index, StandInState initial, bool[]? mask = null)
        {
            Index = index;
            Current = initial;
            Mask = mask;
            _scratch = new double[4 * initial.BoneCount];
        }

        /// <summary>The layer's index in the controller.</summary>
        public int Index { get; }

        /// <summary>The bones this layer drives over the layers below (null: all; the base layer drives all).</summary>
        public bool[]? Mask { get; }

        /// <summary>The state playing (the crossfade's source while in transition).</summary>
        public StandInState Current { get; private set; }

        /// <summary>Seconds into <see cref="Current"/>.</summary>
        public double CurrentTime { get; private set; }

        /// <summary>The crossfade's destination, or null.</summary>
        public StandInState? Next { get; private set; }

        /// <summary>Seconds into <see cref="Next"/>.</summary>
        public double NextTime { get; private set; }

        /// <summary>The crossfade's length and how far it is (seconds).</summary>
        public double Duration { get; private set; }

        /// <summary>Seconds since the crossfade began.</summary>
        public double Elapsed { get; private set; }

        /// <summary>The crossfade's identity.</summary>
        public int TransitionId { get; private set; }

        /// <summary>The destination's weight in the crossfade (0 when none).</summary>
        public double NextWeight => Next == null ? 0 : Math.Min(1, Elapsed / Duration);

        /// <summary>Starts a crossfade into <paramref name="next"/> from its time <paramref name="nextStart"/> over <paramref name="seconds"/>; during one, an interruption.</summary>
        public void CrossFade(StandInState next, double seconds, int transitionId, double nextStart = 0)
        {
            if (Next != null)
            {
                Current = Next;
                CurrentTime = NextTime;
            }

            Next = next;
            NextTime = nextStart;
            Duration = seconds;
            Elapsed = 0;
            TransitionId = transitionId;
        }

        /// <summary>Puts the layer in <paramref name="state"/> at <paramref name="seconds"/> at once (Unity: <c>Animator.PlayInFixedTime</c>): no crossfade.</summary>
        public void Play(StandInState state, double seconds)
        {
            Current = state;
            CurrentTime = seconds;
            Next = null;
            Elapsed = 0;
        }

        /// <summary>
        /// Advances the layer by <paramref name="dt"/> at the parameter value and returns the root's travel over the step (the
        /// states' own travel weighted as the crossfade shows them); a crossfade that ends hands the layer to its destination.
        /// </summary>
        public (double X, double Z) Advance(double dt, double parameter)
        {
            Span<double> r = _scratch;
            Current.Sample(CurrentTime, parameter, out _, r, out double x0, out double z0);
            Current.Sample(CurrentTime + dt, parameter, out _, r, out double x1, out double z1);
            CurrentTime += dt;
            if (Next == null) return (x1 - x0, z1 - z0);
            Next.Sample(NextTime, parameter, out _, r, out double nx0, out double nz0);
            Next.Sample(NextTime + dt, parameter, out _, r, out double nx1, out double nz1);
            NextTime += dt;
            Elapsed += dt;
            double w = NextWeight;
            var step = ((1 - w) * (x1 - x0) + w * (nx1 - nx0), (1 - w) * (z1 - z0) + w * (nz1 - nz0));
            if (Elapsed >= Duration - 1e-9) Play(Next, NextTime);
            return step;
        }

        /// <summary>The layer's pose now (the crossfade blended linearly in weight, per bone SLERP): root height and rotations.</summary>
        public void Evaluate(double parameter, out double height, Span<double> rotations)
        {
            Current.Sample(CurrentTime, parameter, out height, rotations, out _, out _);
            if (Next == null) return;
            Span<double> next = new Span<double>(_scratch, 0, rotations.Length);
            Next.Sample(NextTime, parameter, out double nextHeight, next, out _, out _);
            double w = NextWeight;
            height += w * (nextHeight - height);
            for (int b = 0; b < rotations.Length; b += 4)
            {
                Core.Rotations.Quaternions.Normalize(Core.Rotations.Quaternions.Slerp(Core.Rotations.QuaternionD.Read(rotations, b), Core.Rotations.QuaternionD.Read(next, b), w)).Write(rotations, b);
            }
        }

        /// <summary>The layer's state machine, to run a copy ahead and come back (the off-scene sample).</summary>
        public Snapshot Save() => new Snapshot(Current, CurrentTime, Next, NextTime, Duration, Elapsed, TransitionId);

        /// <summary>Returns to a <see cref="Save"/>d state machine.</summary>
        public void Load(in Snapshot s)
        {
            Current = s.Current;
            CurrentTime = s.CurrentTime;
            Next = s.Next;
            NextTime = s.NextTime;
            Duration = s.Duration;
            Elapsed = s.Elapsed;
            TransitionId = s.TransitionId;
        }

        /// <summary>A layer's state machine at one moment.</summary>
        public readonly struct Snapshot
        {
            public Snapshot(StandInState current, double currentTime, StandInState? next, double nextTime, double duration, double elapsed, int transitionId)
            {
                Current = current;
                CurrentTime = currentTime;
                Next = next;
                NextTime = nextTime;
                Duration = duration;
                Elapsed = elapsed;
                TransitionId = transitionId;
            }

            public StandInState Current { get; }

            public double CurrentTime { get; }

            public StandInState? Next { get; }

            public double NextTime { get; }

            public double Duration { get; }

            public double Elapsed { get; }

            public int TransitionId { get; }
        }

        /// <summary>The layer as the engine reads it for <see cref="AnimatorTransitions"/> (Unity: state infos and transition info).</summary>
        public AnimatorLayerState Read(double parameter)
        {
            var s = new AnimatorLayerState { Layer = Index, StateHash = Current.Hash, TagHash = Current.TagHash, InTransition = Next != null };
            if (Next == null) return s;
            s.NextStateHash = Next.Hash;
            s.NextTagHash = Next.TagHash;
            s.TransitionId = TransitionId;
            s.TransitionSeconds = Duration;
            s.TransitionNormalizedTime = Elapsed / Duration;
            s.NextStateSecondsAtEnd = NextTime + (Duration - Elapsed);
            return s;
        }
    }
}
