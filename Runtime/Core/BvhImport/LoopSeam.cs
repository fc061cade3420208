using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// Where a looping clip cut from mocap should end: a clip of frames a..b wraps from b to a, which looks like the capture
    /// itself when frame a is what came after frame b. The seam's cost is the pose distance between frames a and b + 1 (and,
    /// for the speeds, a + 1 and b + 2), the same measure as between two consecutive frames, so the seam is compared with the
    /// clip's own steps: a seam no larger than the largest step of the clip does not pop.
    /// </summary>
    /// <remarks>
    /// The pose distance is the mean over joints of the angle between their local rotations (degrees), plus the root's height
    /// difference in leg lengths × 90° (a leg length of crouch reads like a right angle); the root's horizontal position and
    /// heading are left out, since root motion carries them on across the loop.
    /// </remarks>
    public static class LoopSeam
    {
        /// <summary>The pose distance between frames <paramref name="f"/> and <paramref name="g"/> of <paramref name="import"/> (see the remarks).</summary>
        public static double PoseDistance(BvhImportResult import, int f, int g)
        {
            if (import == null) throw new ArgumentNullException(nameof(import));
            int n = import.Joints.Count;
            if (f < 0 || g < 0 || f >= import.FrameCount || g >= import.FrameCount) throw new ArgumentOutOfRangeException(nameof(f), $"frames {f} and {g}: expected 0 to {import.FrameCount - 1}");
            float[] r = import.LocalRotations;
            double sum = 0;
            for (int j = 0; j < n; j++)
            {
                int a = (f * n + j) * 4;
                int b = (g * n + j) * 4;
                // Stored x, y, z, w; the root's yaw is part of its rotation, so only its tilt is compared.
                var qa = new QuaternionD(r[a + 3], r[a], r[a + 1], r[a + 2]);
                var qb = new QuaternionD(r[b + 3], r[b], r[b + 1], r[b + 2]);
                sum += j == 0 ? TiltAngle(qa, qb) : Angle(qa, qb);
            }

            float[] p = import.LocalPositions;
            double height = Math.Abs(p[(f * n) * 3 + 1] - p[(g * n) * 3 + 1]);
            return sum / n + 90.0 * height / Math.Max(1e-9, import.LegLength);
        }

        /// <summary>The seam's cost of a loop over frames <paramref name="first"/>..<paramref name="last"/>: pose and speed at the wrap against what follows <paramref name="last"/> in the file.</summary>
        public static double Cost(BvhImportResult import, int first, int last)
        {
            if (import == null) throw new ArgumentNullException(nameof(import));
            if (first < 0 || last + 2 >= import.FrameCount || last <= first) throw new ArgumentOutOfRangeException(nameof(last), $"a loop over frames {first}..{last} needs frames up to {last + 2}; the file has {import.FrameCount}");
            return 0.5 * (PoseDistance(import, first, last + 1) + PoseDistance(import, first + 1, last + 2));
        }

        /// <summary>The largest pose distance between consecutive frames of <paramref name="first"/>..<paramref name="last"/>: the clip's own largest step.</summary>
        public static double LargestStep(BvhImportResult import, int first, int last)
        {
            double most = 0;
            for (int f = first; f < last; f++) most = Math.Max(most, PoseDistance(import, f, f + 1));
            return most;
        }

        /// <summary>The last frame, from <paramref name="first"/> + <paramref name="minFrames"/> - 1 to <paramref name="first"/> + <paramref name="maxFrames"/> - 1, whose loop seam costs least.</summary>
        public static int BestLast(BvhImportResult import, int first, int minFrames, int maxFrames)
        {
            if (import == null) throw new ArgumentNullException(nameof(import));
            if (minFrames < 2 || maxFrames < minFrames) throw new ArgumentOutOfRangeException(nameof(maxFrames), $"lengths {minFrames}..{maxFrames}: expected 2 ≤ min ≤ max");
            int best = -1;
            double bestCost = double.PositiveInfinity;
            for (int last = first + minFrames - 1; last <= first + maxFrames - 1 && last + 2 < import.FrameCount; last++)
            {
                double cost = Cost(import, first, last);
                if (cost < bestCost)
                {
                    bestCost = cost;
                    best = last;
                }
            }

            if (best < 0) throw new ArgumentOutOfRangeException(nameof(minFrames), $"no loop of {minFrames}..{maxFrames} frames from frame {first} fits in {import.FrameCount} frames");
            return best;
        }

        /// <summary>The loop, starting from <paramref name="firstFrom"/> to <paramref name="firstTo"/> and <paramref name="minFrames"/> to <paramref name="maxFrames"/> long, whose seam costs least.</summary>
        public static (int First, int Last) Best(BvhImportResult import, int firstFrom, int firstTo, int minFrames, int maxFrames)
        {
            if (firstTo < firstFrom) throw new ArgumentOutOfRangeException(nameof(firstTo), $"first frames {firstFrom}..{firstTo}: expected from ≤ to");
            (int, int) best = (-1, -1);
            double bestCost = double.PositiveInfinity;
            for (int first = firstFrom; first <= firstTo; first++)
            {
                int last = BestLast(import, first, minFrames, maxFrames);
                double cost = Cost(import, first, last);
                if (cost < bestCost)
                {
                    bestCost = cost;
                    best = (first, last);
                }
            }

            return best;
        }

        private static double Angle(QuaternionD a, QuaternionD b)
        {
            double dot = Math.Abs(a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z);
            return 2.0 * Math.Acos(Math.Min(1.0, dot)) * 180.0 / Math.PI;
        }

        // The angle between the two rotations' up axes (Y up): the tilt, whatever the heading.
        private static double TiltAngle(QuaternionD a, QuaternionD b)
        {
            Vector3D ua = Quaternions.Apply(a, Vector3D.UnitY);
            Vector3D ub = Quaternions.Apply(b, Vector3D.UnitY);
            double dot = Math.Max(-1.0, Math.Min(1.0, ua.X * ub.X + ua.Y * ub.Y + ua.Z * ub.Z));
            return Math.Acos(dot) * 180.0 / Math.PI;
        }
    }
}
