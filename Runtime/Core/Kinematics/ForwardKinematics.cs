using System;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Kinematics
{
    /// <summary>
    /// Local → global: global rotation g_j = g_parent ⊗ q_j and global position
    /// p_j = p_parent + g_parent · t_j, walking joints in index order (parents come first). Same formulas
    /// as the official <c>quat_fk</c>; no renormalisation, so unit input gives unit output up to rounding.
    /// Allocation-free: callers pass flat spans.
    /// </summary>
    public static class ForwardKinematics
    {
        /// <summary>
        /// FK of frames whose non-root joints sit at the skeleton's rest offsets (how the benchmark and
        /// the model see a pose: root translation plus local rotations).
        /// </summary>
        /// <param name="skeleton">Hierarchy and offsets (the offsets of joints 1.. are used).</param>
        /// <param name="frameCount">Number of frames.</param>
        /// <param name="rootPositions">frames × 3 global root positions.</param>
        /// <param name="localRotations">frames × joints × 4 local rotations (w, x, y, z).</param>
        /// <param name="globalPositions">Output, frames × joints × 3.</param>
        /// <param name="globalRotations">Output, frames × joints × 4.</param>
        public static void Compute(
            Skeleton skeleton,
            int frameCount,
            ReadOnlySpan<double> rootPositions,
            ReadOnlySpan<double> localRotations,
            Span<double> globalPositions,
            Span<double> globalRotations)
        {
            int j = skeleton.JointCount;
            Require(rootPositions.Length >= frameCount * 3, nameof(rootPositions), "frames × 3");
            Require(localRotations.Length >= frameCount * j * 4, nameof(localRotations), "frames × joints × 4");
            Require(globalPositions.Length >= frameCount * j * 3, nameof(globalPositions), "frames × joints × 3");
            Require(globalRotations.Length >= frameCount * j * 4, nameof(globalRotations), "frames × joints × 4");
            ReadOnlySpan<int> parents = skeleton.ParentSpan;
            ReadOnlySpan<double> offsets = skeleton.OffsetSpan;
            for (int f = 0; f < frameCount; f++)
            {
                ComputeFrame(
                    parents,
                    offsets,
                    Vector3D.Read(rootPositions, 3 * f),
                    localRotations.Slice(f * j * 4, j * 4),
                    globalPositions.Slice(f * j * 3, j * 3),
                    globalRotations.Slice(f * j * 4, j * 4));
            }
        }

        /// <summary>
        /// FK of frames with a local translation for every joint (e.g. a BVH clip whose joints carry
        /// position channels; the root's local translation is its global position).
        /// </summary>
        public static void ComputeWithLocalPositions(
            Skeleton skeleton,
            int frameCount,
            ReadOnlySpan<double> localPositions,
            ReadOnlySpan<double> localRotations,
            Span<double> globalPositions,
            Span<double> globalRotations)
        {
            int j = skeleton.JointCount;
            Require(localPositions.Length >= frameCount * j * 3, nameof(localPositions), "frames × joints × 3");
            Require(localRotations.Length >= frameCount * j * 4, nameof(localRotations), "frames × joints × 4");
            Require(globalPositions.Length >= frameCount * j * 3, nameof(globalPositions), "frames × joints × 3");
            Require(globalRotations.Length >= frameCount * j * 4, nameof(globalRotations), "frames × joints × 4");
            ReadOnlySpan<int> parents = skeleton.ParentSpan;
            for (int f = 0; f < frameCount; f++)
            {
                ReadOnlySpan<double> lp = localPositions.Slice(f * j * 3, j * 3);
                ComputeFrame(
                    parents,
                    lp,
                    Vector3D.Read(lp, 0),
                    localRotations.Slice(f * j * 4, j * 4),
                    globalPositions.Slice(f * j * 3, j * 3),
                    globalRotations.Slice(f * j * 4, j * 4));
            }
        }

        /// <summary>FK of one frame: <paramref name="translations"/> gives joint j's local translation at 3j (the root's is ignored).</summary>
        public static void ComputeFrame(
            ReadOnlySpan<int> parents,
            ReadOnlySpan<double> translations,
            Vector3D rootPosition,
            ReadOnlySpan<double> localRotations,
            Span<double> globalPositions,
            Span<double> globalRotations)
        {
            int jointCount = parents.Length;
            rootPosition.Write(globalPositions, 0);
            globalRotations[0] = localRotations[0];
            globalRotations[1] = localRotations[1];
            globalRotations[2] = localRotations[2];
            globalRotations[3] = localRotations[3];
            for (int k = 1; k < jointCount; k++)
            {
                int parent = parents[k];
                QuaternionD gParent = QuaternionD.Read(globalRotations, 4 * parent);
                Vector3D pParent = Vector3D.Read(globalPositions, 3 * parent);
                Vector3D t = Vector3D.Read(translations, 3 * k);
                (pParent + Quaternions.Apply(gParent, t)).Write(globalPositions, 3 * k);
                Quaternions.Multiply(gParent, QuaternionD.Read(localRotations, 4 * k)).Write(globalRotations, 4 * k);
            }
        }

        private static void Require(bool condition, string name, string shape)
        {
            if (!condition) throw new ArgumentException($"{name} is too short; expected {shape} values", name);
        }
    }
}
