using System;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Evaluation.Metrics;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>
    /// How close a baked clip is to the motion its keys were taken from, over the filled (non-key) frames:
    /// mean global joint position error in the clip's units, L2Q and (given position statistics) L2P,
    /// each the mean over filled frames of a per-frame norm as in the LaFAN1 benchmark.
    /// </summary>
    /// <remarks>
    /// Unlike the benchmark, nothing is windowed: frames are scored where they are in the file (no
    /// centring, no turning to face +X), so L2P's per-axis standard deviations apply to the file's own
    /// axes. L2Q compares global quaternions after taking each predicted one in the hemisphere of the
    /// truth (q and −q are one rotation; a baked clip's sign convention is its own, not the file's).
    /// Positions come from FK with each clip's own local translations.
    /// </remarks>
    public readonly struct BakeAccuracy
    {
        private BakeAccuracy(int frames, double positionError, double l2q, double l2p)
        {
            Frames = frames;
            MeanPositionError = positionError;
            L2Q = l2q;
            L2P = l2p;
        }

        /// <summary>Filled frames scored.</summary>
        public int Frames { get; }

        /// <summary>Mean over filled frames and joints of the distance between baked and true global joint positions (clip units).</summary>
        public double MeanPositionError { get; }

        /// <summary>Mean over filled frames of ‖ĝ − g‖ over all joints' global quaternion components.</summary>
        public double L2Q { get; }

        /// <summary>Mean over filled frames of the standardised global position error; NaN without statistics.</summary>
        public double L2P { get; }

        /// <summary>
        /// Scores <paramref name="baked"/> (from a <see cref="ClipBaker"/>)
        /// against <paramref name="truth"/>, the clip the keys were taken from.
        /// </summary>
        /// <param name="truth">The source clip (all frames).</param>
        /// <param name="baked">The baked clip: source frames keys[0]..keys[last].</param>
        /// <param name="keys">The key frame indices (increasing) of <paramref name="truth"/>; frames between them are scored.</param>
        /// <param name="standardDeviations">joints × 3 position standard deviations for L2P (e.g. the benchmark statistics'), or null.</param>
        public static BakeAccuracy Measure(MotionClip truth, MotionClip baked, System.Collections.Generic.IReadOnlyList<int> keys, ReadOnlySpan<double> standardDeviations = default)
        {
            if (truth == null) throw new ArgumentNullException(nameof(truth));
            if (baked == null) throw new ArgumentNullException(nameof(baked));
            if (keys == null || keys.Count < 2) throw new ArgumentException("expected at least two keys", nameof(keys));
            Skeleton skeleton = truth.Skeleton;
            int j = skeleton.JointCount;
            int first = keys[0];
            if (baked.Skeleton.JointCount != j || baked.FrameCount != keys[keys.Count - 1] - first + 1 || keys[keys.Count - 1] >= truth.FrameCount)
            {
                throw new ArgumentException("the clips do not match the keys; expected the source clip and the clip baked from it with these keys");
            }

            bool withL2P = !standardDeviations.IsEmpty;
            if (withL2P && standardDeviations.Length != j * 3)
            {
                throw new ArgumentException($"{standardDeviations.Length} standard deviations; expected joints × 3 = {j * 3}", nameof(standardDeviations));
            }

            var truePositions = new double[j * 3];
            var trueRotations = new double[j * 4];
            var bakedPositions = new double[j * 3];
            var bakedRotations = new double[j * 4];
            double positionSum = 0, l2qSum = 0, l2pSum = 0;
            int frames = 0;
            for (int i = 0; i + 1 < keys.Count; i++)
            {
                for (int f = keys[i] + 1; f < keys[i + 1]; f++)
                {
                    Frame(truth, f, truePositions, trueRotations);
                    Frame(baked, f - first, bakedPositions, bakedRotations);
                    for (int k = 0; k < j; k++)
                    {
                        positionSum += (Vector3D.Read(bakedPositions, 3 * k) - Vector3D.Read(truePositions, 3 * k)).Length;
                        QuaternionD q = QuaternionD.Read(bakedRotations, 4 * k);
                        if (Quaternions.Dot(q, QuaternionD.Read(trueRotations, 4 * k)) < 0) q.Negated.Write(bakedRotations, 4 * k);
                    }

                    l2qSum += TransitionMetrics.SumL2Q(bakedRotations, trueRotations, 1, j);
                    if (withL2P) l2pSum += TransitionMetrics.SumL2P(bakedPositions, truePositions, 1, j, standardDeviations);
                    frames++;
                }
            }

            if (frames == 0) return new BakeAccuracy(0, 0, 0, withL2P ? 0 : double.NaN);
            return new BakeAccuracy(frames, positionSum / (frames * (double)j), l2qSum / frames, withL2P ? l2pSum / frames : double.NaN);
        }

        private static void Frame(MotionClip clip, int frame, double[] positions, double[] rotations)
        {
            int j = clip.Skeleton.JointCount;
            ForwardKinematics.ComputeWithLocalPositions(
                clip.Skeleton, 1,
                clip.LocalPositions.AsSpan(frame * j * 3, j * 3),
                clip.LocalRotations.AsSpan(frame * j * 4, j * 4),
                positions, rotations);
        }
    }
}
