using System;

namespace DeltaInterpolator.Core.Rotations
{
    /// <summary>
    /// The official LaFAN1 benchmark's slerp between two fixed quaternions, with the per-pair work
    /// (hemisphere flip, arccos, sine) done once so that sampling many weights costs only the weights.
    /// <see cref="Quaternions.Slerp"/> is this struct used once; the SLERP baseline and the neural
    /// decoder build one per joint per transition and sample it for every missing frame.
    /// </summary>
    internal readonly struct SlerpPair
    {
        private readonly QuaternionD _to;
        private readonly bool _linear;
        private readonly double _omega;
        private readonly double _sinOmega;

        /// <summary>Prepares slerp from <paramref name="from"/> to <paramref name="to"/> (not normalised here).</summary>
        public SlerpPair(QuaternionD from, QuaternionD to)
        {
            From = from;
            double d = Quaternions.Dot(from, to);
            if (d < 0.0)
            {
                // Flip the second into the first's hemisphere: the shorter of the two arcs.
                d = -d;
                to = to.Negated;
            }

            _to = to;
            // Near-parallel: sin ω → 0 makes the spherical weights ill-conditioned; use linear weights.
            _linear = 1.0 - d < 0.01;
            _omega = _linear ? 0.0 : Math.Acos(d);
            _sinOmega = _linear ? 1.0 : Math.Sin(_omega);
        }

        /// <summary>The start quaternion, as given.</summary>
        public QuaternionD From { get; }

        /// <summary>The (unnormalised) slerp at weight <paramref name="t"/>: <see cref="From"/> at 0, the end at 1.</summary>
        public QuaternionD At(double t)
        {
            double wa = _linear ? 1.0 - t : Math.Sin((1.0 - t) * _omega) / _sinOmega;
            double wb = _linear ? t : Math.Sin(t * _omega) / _sinOmega;
            QuaternionD a = From, b = _to;
            return new QuaternionD(
                wa * a.W + wb * b.W, wa * a.X + wb * b.X, wa * a.Y + wb * b.Y, wa * a.Z + wb * b.Z);
        }
    }
}
