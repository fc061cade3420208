using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>
    /// How much a baked clip's feet slide where the ground truth's feet are planted: the mean horizontal
    /// speed, in leg lengths per second, of each foot joint (ankle, toe) of the result on the filled
    /// (non-key) frames where that joint of the truth is in contact.
    /// </summary>
    /// <remarks>
    /// <para>Contact is decided on the truth alone, so every method is scored on the same frames: a foot
    /// joint is planted on a frame when it is within <see cref="ContactHeight"/> (3 %) of a leg length above
    /// the clip's ground level and its horizontal speed is below <see cref="ContactSpeed"/> (15 % of a leg
    /// length per second). The ground level is the 5th percentile, over the scored span's frames (first to
    /// last key), of the truth's lowest foot-joint height. Speeds are central differences over the frames
    /// around (a filled frame always has both), horizontal (X, Z) only: a foot may roll and lift, it should
    /// not slide.</para>
    /// <para>The truth measured against itself (<see cref="OfTruth"/>) is the floor no method can beat:
    /// motion capture's planted feet creep a little, and the speed threshold lets them.</para>
    /// <para>Leg length is <see cref="FootRig.LegLength"/> (<see cref="Core.Retargeting.SkeletonMap"/>'s), so the
    /// number is comparable across skeletons and units; positions come from FK with each clip's own local
    /// translations.</para>
    /// </remarks>
    public readonly struct FootSkating
    {
        /// <summary>Height above the ground level, in leg lengths, under which a truth foot joint may be in contact.</summary>
        public const double ContactHeight = 0.03;

        /// <summary>Horizontal speed, in leg lengths per second, under which a truth foot joint may be in contact.</summary>
        public const double ContactSpeed = 0.15;

        /// <summary>The percentile of the lowest foot-joint height that is the clip's ground level.</summary>
        public const double GroundPercentile = 5;

        private FootSkating(int samples, double meanSpeed, double ground)
        {
            ContactSamples = samples;
            MeanSpeed = meanSpeed;
            Ground = ground;
        }

        /// <summary>(Filled frame, foot joint) pairs where the truth is planted: the samples averaged.</summary>
        public int ContactSamples { get; }

        /// <summary>Mean horizontal speed of the result's planted foot joints, leg lengths per second (lower is better); NaN without samples.</summary>
        public double MeanSpeed { get; }

        /// <summary>The ground level used (height in the clip's units).</summary>
        public double Ground { get; }

        /// <summary>
        /// Scores <paramref name="result"/> (a bake of <paramref name="truth"/>'s keys) on the frames where the truth's feet are planted.
        /// </summary>
        /// <param name="truth">The source clip (all frames).</param>
        /// <param name="result">The baked clip: the truth's frames keys[0]..keys[last], same skeleton.</param>
        /// <param name="keys">The key frame indices of <paramref name="truth"/>, increasing; frames between them are scored.</param>
        /// <param name="feet">The skeleton's feet and leg length.</param>
        public static FootSkating Measure(MotionClip truth, MotionClip result, IReadOnlyList<int> keys, FootRig feet)
        {
            if (truth == null) throw new ArgumentNullException(nameof(truth));
            if (result == null) throw new ArgumentNullException(nameof(result));
            if (feet == null) throw new ArgumentNullException(nameof(feet));
            if (keys == null || keys.Count < 2) throw new ArgumentException("expected at least two keys", nameof(keys));
            int first = keys[0], last = keys[keys.Count - 1];
            int j = truth.Skeleton.JointCount;
            if (result.Skeleton.JointCount != j || feet.Skeleton.JointCount != j || result.FrameCount != last - first + 1 || last >= truth.FrameCount || first < 0)
            {
                throw new ArgumentException("the clips, keys and feet do not match; expected the source clip, the clip baked from it with these keys, and the rig of their skeleton");
            }

            for (int i = 1; i < keys.Count; i++)
            {
                if (keys[i] <= keys[i - 1]) throw new ArgumentException($"key {keys[i]} after {keys[i - 1]}; expected increasing keys", nameof(keys));
            }

            int frames = last - first + 1;
            IReadOnlyList<int> footJoints = feet.FootJoints;
            int n = footJoints.Count;
            double[] truthFeet = FootPositions(truth, first, frames, footJoints);
            double[] resultFeet = ReferenceEquals(truth, result) ? truthFeet : FootPositions(result, 0, frames, footJoints);

            double ground = GroundLevel(truthFeet, n);
            double leg = feet.LegLength;
            double sum = 0;
            int samples = 0;
            int stride = n * 3;
            for (int i = 0; i + 1 < keys.Count; i++)
            {
                int from = keys[i] - first, count = keys[i + 1] - keys[i] + 1;
                Accumulate(new ReadOnlySpan<double>(truthFeet, from * stride, count * stride), new ReadOnlySpan<double>(resultFeet, from * stride, count * stride),
                    n, truth.FrameTime, result.FrameTime, ground, leg, ref sum, ref samples);
            }

            return new FootSkating(samples, samples == 0 ? double.NaN : sum / samples, ground);
        }

        /// <summary>
        /// Adds one gap's samples to <paramref name="sum"/> (speeds in leg lengths per second) and
        /// <paramref name="samples"/>: the foot-joint positions (frames × <paramref name="footJoints"/> × 3) of the
        /// key before the gap, its filled frames and the key after it, for the truth and the result. The filled
        /// frames are scored; the keys give their neighbours. Allocation-free (the benchmark calls it per window).
        /// </summary>
        /// <param name="truthFeet">The truth's foot-joint positions over the gap and its two keys.</param>
        /// <param name="resultFeet">The result's, same frames.</param>
        /// <param name="footJoints">Foot joints per frame.</param>
        /// <param name="truthFrameTime">Seconds per truth frame.</param>
        /// <param name="resultFrameTime">Seconds per result frame.</param>
        /// <param name="ground">The clip's ground level (<see cref="GroundLevel"/>).</param>
        /// <param name="legLength">Leg length, in the positions' units.</param>
        /// <param name="sum">Running sum of the result's speeds on planted truth samples (leg lengths per second).</param>
        /// <param name="samples">Running count of those samples.</param>
        public static void Accumulate(ReadOnlySpan<double> truthFeet, ReadOnlySpan<double> resultFeet, int footJoints, double truthFrameTime, double resultFrameTime,
            double ground, double legLength, ref double sum, ref int samples)
        {
            int n = footJoints;
            int frames = truthFeet.Length / (3 * n);
            double heightLimit = ground + ContactHeight * legLength;
            double speedLimit = ContactSpeed * legLength;
            for (int f = 1; f + 1 < frames; f++)
            {
                for (int k = 0; k < n; k++)
                {
                    if (truthFeet[(f * n + k) * 3 + 1] > heightLimit) continue;
                    if (HorizontalSpeed(truthFeet, f, k, n, 2 * truthFrameTime) >= speedLimit) continue;
                    sum += HorizontalSpeed(resultFeet, f, k, n, 2 * resultFrameTime) / legLength;
                    samples++;
                }
            }
        }

        /// <summary>
        /// Which foot joints are planted on each frame by the contact rule the measure applies to the truth
        /// (within <see cref="ContactHeight"/> of <paramref name="ground"/>, slower than <see cref="ContactSpeed"/>):
        /// frames × <paramref name="footJoints"/> flags. Speeds are central differences (one-sided on the first and
        /// last frame). The preview marks these, on any track.
        /// </summary>
        public static bool[] Planted(ReadOnlySpan<double> feet, int footJoints, double frameTime, double ground, double legLength)
        {
            var grounds = new double[footJoints];
            Array.Fill(grounds, ground);
            return Planted(feet, footJoints, frameTime, grounds, legLength);
        }

        /// <summary>
        /// The contact labels the network learns and is scored against (issue 29; Python <c>contacts.planted</c>, golden
        /// vectors in <c>Tests/Fixtures~/contact-labels.json</c>): the rule of <see cref="Planted(ReadOnlySpan{double}, int, double, double, double)"/>
        /// with each foot joint measured from its own ground level (<see cref="GroundLevels"/>). An ankle stands a
        /// heel's height above the floor when the foot is flat, more than the 3 % band, so from the lowest joint's
        /// level (the measure's <see cref="GroundLevel"/>) a CMU ankle was planted on 0.004 % of the training frames;
        /// from its own, on about 23 % of them, as often as a toe.
        /// </summary>
        public static bool[] ContactLabels(ReadOnlySpan<double> feet, int footJoints, double frameTime, double legLength)
            => Planted(feet, footJoints, frameTime, GroundLevels(feet, footJoints), legLength);

        /// <summary>
        /// <see cref="Planted(ReadOnlySpan{double}, int, double, double, double)"/> with a ground level per foot joint
        /// (<paramref name="grounds"/>, one per joint).
        /// </summary>
        public static bool[] Planted(ReadOnlySpan<double> feet, int footJoints, double frameTime, ReadOnlySpan<double> grounds, double legLength)
        {
            int n = footJoints;
            if (grounds.Length != n) throw new ArgumentException($"{grounds.Length} ground levels for {n} foot joints; expected one per joint", nameof(grounds));
            int frames = feet.Length / (3 * n);
            var planted = new bool[frames * n];
            double speedLimit = ContactSpeed * legLength;
            for (int f = 0; f < frames; f++)
            {
                int before = Math.Max(0, f - 1), after = Math.Min(frames - 1, f + 1);
                if (after == before) continue;
                for (int k = 0; k < n; k++)
                {
                    if (feet[(f * n + k) * 3 + 1] > grounds[k] + ContactHeight * legLength) continue;
                    int a = (after * n + k) * 3, b = (before * n + k) * 3;
                    double dx = feet[a] - feet[b], dz = feet[a + 2] - feet[b + 2];
                    planted[f * n + k] = Math.Sqrt(dx * dx + dz * dz) / ((after - before) * frameTime) < speedLimit;
                }
            }

            return planted;
        }

        /// <summary>
        /// A clip's ground level: the <see cref="GroundPercentile"/>th percentile over its frames of the lowest
        /// foot-joint height (<paramref name="feet"/>: frames × <paramref name="footJoints"/> × 3 positions).
        /// </summary>
        public static double GroundLevel(ReadOnlySpan<double> feet, int footJoints)
        {
            int frames = feet.Length / (3 * footJoints);
            var lowest = new double[frames];
            for (int f = 0; f < frames; f++)
            {
                double low = double.PositiveInfinity;
                for (int k = 0; k < footJoints; k++) low = Math.Min(low, feet[(f * footJoints + k) * 3 + 1]);
                lowest[f] = low;
            }

            return Percentile(lowest, GroundPercentile);
        }

        /// <summary>
        /// Each foot joint's own ground level over a span (<paramref name="feet"/>: frames × <paramref name="footJoints"/> × 3
        /// positions): the <see cref="GroundPercentile"/>th percentile of that joint's height. Empty positions give NaN levels.
        /// </summary>
        public static double[] GroundLevels(ReadOnlySpan<double> feet, int footJoints)
        {
            int frames = feet.Length / (3 * footJoints);
            var levels = new double[footJoints];
            var heights = new double[frames];
            for (int k = 0; k < footJoints; k++)
            {
                for (int f = 0; f < frames; f++) heights[f] = feet[(f * footJoints + k) * 3 + 1];
                levels[k] = frames == 0 ? double.NaN : Percentile(heights, GroundPercentile);
            }

            return levels;
        }

        /// <summary>The truth scored against itself over the same frames: the floor no method can beat.</summary>
        public static FootSkating OfTruth(MotionClip truth, IReadOnlyList<int> keys, FootRig feet)
        {
            if (truth == null) throw new ArgumentNullException(nameof(truth));
            if (keys == null || keys.Count < 2) throw new ArgumentException("expected at least two keys", nameof(keys));
            int first = keys[0], count = keys[keys.Count - 1] - first + 1;
            if (first == 0 && count == truth.FrameCount) return Measure(truth, truth, keys, feet);
            if (first < 0 || keys[keys.Count - 1] >= truth.FrameCount) throw new ArgumentException("the keys are not frames of the truth", nameof(keys));
            int j = truth.Skeleton.JointCount;
            var positions = new double[count * j * 3];
            var rotations = new double[count * j * 4];
            Array.Copy(truth.LocalPositions, first * j * 3, positions, 0, positions.Length);
            Array.Copy(truth.LocalRotations, first * j * 4, rotations, 0, rotations.Length);
            return Measure(truth, new MotionClip(truth.Skeleton, count, truth.FrameTime, positions, rotations), keys, feet);
        }

        /// <summary>frames × foot joints × 3 global positions of <paramref name="clip"/>'s frames start.. (FK with its local translations).</summary>
        public static double[] FootPositions(MotionClip clip, int start, int frames, IReadOnlyList<int> footJoints)
        {
            int j = clip.Skeleton.JointCount, n = footJoints.Count;
            var globalPositions = new double[j * 3];
            var globalRotations = new double[j * 4];
            var result = new double[frames * n * 3];
            for (int f = 0; f < frames; f++)
            {
                ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, 1,
                    clip.LocalPositions.AsSpan((start + f) * j * 3, j * 3), clip.LocalRotations.AsSpan((start + f) * j * 4, j * 4),
                    globalPositions, globalRotations);
                for (int k = 0; k < n; k++) Array.Copy(globalPositions, footJoints[k] * 3, result, (f * n + k) * 3, 3);
            }

            return result;
        }

        /// <summary>|(p[f+1] − p[f−1]) in X, Z| / 2Δt for foot joint k (f has a frame on either side).</summary>
        private static double HorizontalSpeed(ReadOnlySpan<double> feet, int f, int k, int n, double twoFrameTimes)
        {
            int next = ((f + 1) * n + k) * 3, previous = ((f - 1) * n + k) * 3;
            double dx = feet[next] - feet[previous], dz = feet[next + 2] - feet[previous + 2];
            return Math.Sqrt(dx * dx + dz * dz) / twoFrameTimes;
        }

        /// <summary>The p-th percentile with linear interpolation between order statistics (NumPy's default).</summary>
        internal static double Percentile(double[] values, double p)
        {
            var sorted = (double[])values.Clone();
            Array.Sort(sorted);
            double rank = p / 100.0 * (sorted.Length - 1);
            int lo = (int)Math.Floor(rank);
            int hi = Math.Min(lo + 1, sorted.Length - 1);
            return sorted[lo] + (rank - lo) * (sorted[hi] - sorted[lo]);
        }
    }
}
