using System;
using System.Collections.Generic;
using System.Linq;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Tests.OnnxRuntime
{
    /// <summary>
    /// Issue 27's smoothness bounds over consecutive shown frames: no joint turns more than 1.25 × the larger of the reference turns
    /// (SLERP's, and the target state's own, over the same step) plus 0.5°, and the root's horizontal speed changes by at most 20 % of
    /// the state's own root speed plus 0.1 m/s. Records the worst margins so a test reports its measured maxima.
    /// </summary>
    public sealed class StepBounds
    {
        private const double TurnFactor = 1.25;
        private const double TurnSlackDegrees = 0.5;
        private const double SpeedShare = 0.2;
        private const double SpeedSlack = 0.1;
        private double[]? _previousRotations;
        private double[]? _previousRoot;
        private double _previousTime;
        private double _previousSpeed = double.NaN;
        private readonly Dictionary<string, (double Share, int Steps)> _worstByPhase = new Dictionary<string, (double, int)>();
        private readonly List<string> _phases = new List<string>();

        /// <summary>The worst turn as a share of its bound (≤ 1 passes), and where.</summary>
        public double WorstTurnShare { get; private set; }

        /// <summary>Where <see cref="WorstTurnShare"/> happened: frame time, bone, turn (degrees) and bound (degrees).</summary>
        public string WorstTurnAt { get; private set; } = "";

        /// <summary>The worst speed change as a share of its bound (≤ 1 passes), and where.</summary>
        public double WorstSpeedShare { get; private set; }

        /// <summary>Where <see cref="WorstSpeedShare"/> happened.</summary>
        public string WorstSpeedAt { get; private set; } = "";

        /// <summary>What the runtime shows in the next steps (e.g. "SLERP", "ease-in", "network", "arrival"), set by the test before <see cref="Frame"/>, for <see cref="Trace"/> and <see cref="WorstByPhase"/>.</summary>
        public string Phase { get; set; } = "";

        /// <summary>Per step: its phase, time, the worst joint's turn as a share of its bound, which joint, its turn and its references' turns (for reports).</summary>
        public List<string> Trace { get; } = new List<string>();

        /// <summary>Steps checked.</summary>
        public int Steps { get; private set; }

        /// <summary>Failures (bone or root, time, values), empty when every step is within its bounds.</summary>
        public List<string> Failures { get; } = new List<string>();

        /// <summary>
        /// A frame shown at <paramref name="time"/>; the step from the previous one is checked against the references' turns over it
        /// (<paramref name="slerpFrom"/> → <paramref name="slerpTo"/>, <paramref name="ownFrom"/> → <paramref name="ownTo"/>: rotations) and
        /// the state's own root speed over it (<paramref name="ownSpeed"/>, m/s).
        /// </summary>
        public void Frame(double time, double[] root, double[] rotations, double[] slerpFrom, double[] slerpTo, double[] ownFrom, double[] ownTo, double ownSpeed)
        {
            if (_previousRotations != null && _previousRoot != null)
            {
                double dt = time - _previousTime;
                double stepShare = 0;
                string stepAt = "";
                for (int i = 0; i < rotations.Length; i += 4)
                {
                    double turn = Degrees(QuaternionD.Read(_previousRotations, i), QuaternionD.Read(rotations, i));
                    double slerp = Degrees(QuaternionD.Read(slerpFrom, i), QuaternionD.Read(slerpTo, i));
                    double own = Degrees(QuaternionD.Read(ownFrom, i), QuaternionD.Read(ownTo, i));
                    double bound = TurnFactor * Math.Max(slerp, own) + TurnSlackDegrees;
                    if (turn / bound > WorstTurnShare)
                    {
                        WorstTurnShare = turn / bound;
                        WorstTurnAt = $"t = {time:F4} s, bone {i / 4}: {turn:F3}° (SLERP {slerp:F3}°, own {own:F3}°, bound {bound:F3}°)";
                    }

                    if (turn / bound > stepShare)
                    {
                        stepShare = turn / bound;
                        stepAt = $"bone {i / 4,2} {turn,6:F3}° (SLERP {slerp:F3}°, own {own:F3}°)";
                    }

                    if (turn > bound) Failures.Add($"t = {time:F4} s, bone {i / 4} turned {turn:F3}° > {bound:F3}° (SLERP {slerp:F3}°, own {own:F3}°)");
                }

                double speed = Math.Sqrt(Square(root[0] - _previousRoot[0]) + Square(root[2] - _previousRoot[2])) / dt;
                if (!double.IsNaN(_previousSpeed))
                {
                    double change = Math.Abs(speed - _previousSpeed);
                    double bound = SpeedShare * ownSpeed + SpeedSlack;
                    if (change / bound > WorstSpeedShare)
                    {
                        WorstSpeedShare = change / bound;
                        WorstSpeedAt = $"t = {time:F4} s: {_previousSpeed:F3} → {speed:F3} m/s (own {ownSpeed:F3} m/s, bound {bound:F3} m/s)";
                    }

                    if (change > bound) Failures.Add($"t = {time:F4} s, root speed {_previousSpeed:F3} → {speed:F3} m/s, change > {bound:F3} m/s (own {ownSpeed:F3} m/s)");
                }

                Trace.Add($"t = {time:F4} s {Phase,-14} {stepShare,5:P0} {stepAt}");
                if (!_worstByPhase.TryGetValue(Phase, out (double Share, int Steps) worst)) _phases.Add(Phase);
                _worstByPhase[Phase] = (Math.Max(worst.Share, stepShare), worst.Steps + 1);
                _previousSpeed = speed;
                Steps++;
            }

            _previousRotations = (double[])rotations.Clone();
            _previousRoot = (double[])root.Clone();
            _previousTime = time;
        }

        /// <summary>The worst turn share in each phase, in the order the phases came (e.g. "SLERP 68 % (1), ease-in 238 % (2), …").</summary>
        public string WorstByPhase() => string.Join(", ", _phases.Select(p => $"{(p.Length == 0 ? "-" : p)} {_worstByPhase[p].Share:P0} ({_worstByPhase[p].Steps} steps)"));

        /// <summary>The worst margins, for the test's output.</summary>
        public override string ToString() => $"{Steps} steps; worst turn {WorstTurnShare:P0} of its bound at {WorstTurnAt}; worst root speed change {WorstSpeedShare:P0} of its bound at {WorstSpeedAt}";

        /// <summary>The angle of the rotation between <paramref name="a"/> and <paramref name="b"/>, in degrees (q and −q the same).</summary>
        public static double Degrees(QuaternionD a, QuaternionD b)
        {
            a = Quaternions.Normalize(a);
            b = Quaternions.Normalize(b);
            if (Quaternions.Dot(a, b) < 0) b = b.Negated;
            // 2·atan2(|a − b|, |a + b|) is the 4-D angle, accurate near 0; the rotation angle is twice it.
            double diff = new QuaternionD(a.W - b.W, a.X - b.X, a.Y - b.Y, a.Z - b.Z).Length;
            double sum = new QuaternionD(a.W + b.W, a.X + b.X, a.Y + b.Y, a.Z + b.Z).Length;
            return 4.0 * Math.Atan2(diff, sum) * 180 / Math.PI;
        }

        private static double Square(double x) => x * x;
    }
}
