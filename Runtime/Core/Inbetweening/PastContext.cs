using System;

namespace DeltaInterpolator.Core.Inbetweening
{
    /// <summary>
    /// Fills a <see cref="Transition"/>'s key frames from dense motion: the past keys from the frames
    /// that end at a given frame (under a <see cref="ShortContextPolicy"/> when fewer exist than the
    /// transition holds) and the target key from one frame. Shared by the benchmark and the clip baker,
    /// so both feed a model the same way. Allocation-free.
    /// </summary>
    public static class PastContext
    {
        /// <summary>
        /// How many past keys a transition needs to feed <paramref name="available"/> frames to a model
        /// that wants <paramref name="wanted"/> under <paramref name="policy"/>: all wanted frames when
        /// enough exist; otherwise the available ones (<see cref="ShortContextPolicy.FeedAvailable"/>) or
        /// the wanted count, padded (<see cref="ShortContextPolicy.RepeatEarliest"/>).
        /// </summary>
        public static int PastFrames(int available, int wanted, ShortContextPolicy policy)
        {
            if (available < 1) throw new ArgumentOutOfRangeException(nameof(available), "at least one past frame must exist");
            if (wanted < 1) throw new ArgumentOutOfRangeException(nameof(wanted), "at least one past frame must be wanted");
            if (available >= wanted) return wanted;
            return policy == ShortContextPolicy.FeedAvailable ? available : wanted;
        }

        /// <summary>
        /// Writes the transition's <see cref="Transition.PastFrames"/> past keys from frames
        /// <c>lastFrame − available + 1 .. lastFrame</c> of the dense motion: the last of them at key
        /// P − 1, and, when P exceeds <paramref name="available"/>, the earliest of them repeated into
        /// keys 0 .. P − available − 1.
        /// </summary>
        /// <param name="transition">The transition whose past keys are written.</param>
        /// <param name="rootPositions">frames × 3 root positions.</param>
        /// <param name="localRotations">frames × joints × 4 local rotations (w, x, y, z).</param>
        /// <param name="lastFrame">The frame that becomes the last past key (the reference frame).</param>
        /// <param name="available">How many frames up to <paramref name="lastFrame"/> may be used (≥ 1).</param>
        public static void FillPast(Transition transition, ReadOnlySpan<double> rootPositions, ReadOnlySpan<double> localRotations, int lastFrame, int available)
        {
            int p = transition.PastFrames;
            int used = Math.Min(p, available);
            if (used < 1) throw new ArgumentOutOfRangeException(nameof(available), "at least one past frame must be available");
            int first = lastFrame - used + 1;
            if (first < 0) throw new ArgumentOutOfRangeException(nameof(lastFrame), $"frame {first} would be needed before frame 0");
            int stride = transition.Skeleton.JointCount * 4;
            int pad = p - used;
            Span<double> keyRoot = transition.KeyRootPositions;
            Span<double> keyRot = transition.KeyLocalRotations;
            for (int k = 0; k < p; k++)
            {
                int frame = k < pad ? first : first + (k - pad);
                rootPositions.Slice(frame * 3, 3).CopyTo(keyRoot.Slice(k * 3, 3));
                localRotations.Slice(frame * stride, stride).CopyTo(keyRot.Slice(k * stride, stride));
            }
        }

        /// <summary>Writes the transition's target key from frame <paramref name="frame"/> of the dense motion.</summary>
        public static void FillTarget(Transition transition, ReadOnlySpan<double> rootPositions, ReadOnlySpan<double> localRotations, int frame)
        {
            int stride = transition.Skeleton.JointCount * 4;
            int t = transition.TargetKey;
            rootPositions.Slice(frame * 3, 3).CopyTo(transition.KeyRootPositions.AsSpan(t * 3, 3));
            localRotations.Slice(frame * stride, stride).CopyTo(transition.KeyLocalRotations.AsSpan(t * stride, stride));
        }
    }
}
