using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// Where each joint's values sit on a motion line, worked out once from the CHANNELS lines: the
    /// columns of its X, Y, Z position and of its three rotation angles, and the Euler order those angles
    /// compose in. <see cref="ApplyRow"/> turns one line of values into local positions (a joint without
    /// position channels sits at its offset) and local rotations (quaternions; identity without rotation
    /// channels).
    /// </summary>
    internal sealed class BvhChannelPlan
    {
        private readonly int[] _positionColumns;
        private readonly int[] _rotationColumns;
        private readonly EulerOrder[] _orders;
        private readonly bool[] _hasPosition;
        private readonly bool[] _hasRotation;
        private readonly double[] _offsets;

        /// <summary>Plans the columns of <paramref name="channels"/> (one list per joint, file order).</summary>
        /// <param name="channels">Each joint's channels as its CHANNELS line lists them.</param>
        /// <param name="offsets">Joint offsets, 3 per joint: the position of joints without position channels.</param>
        public BvhChannelPlan(BvhChannel[][] channels, double[] offsets)
        {
            int jointCount = channels.Length;
            JointCount = jointCount;
            _offsets = offsets;
            _positionColumns = new int[jointCount * 3];
            _rotationColumns = new int[jointCount * 3];
            _orders = new EulerOrder[jointCount];
            _hasPosition = new bool[jointCount];
            _hasRotation = new bool[jointCount];
            int column = 0;
            Span<int> axes = stackalloc int[3];
            for (int j = 0; j < jointCount; j++)
            {
                int r = 0;
                foreach (BvhChannel c in channels[j])
                {
                    if (c.IsRotation())
                    {
                        _rotationColumns[3 * j + r] = column;
                        axes[r++] = c.Axis();
                        _hasRotation[j] = true;
                    }
                    else
                    {
                        _positionColumns[3 * j + c.Axis()] = column;
                        _hasPosition[j] = true;
                    }

                    column++;
                }

                _orders[j] = r == 3 ? EulerOrders.FromAxes(axes[0], axes[1], axes[2]) : EulerOrder.Xyz;
            }

            ChannelCount = column;
        }

        /// <summary>Number of joints.</summary>
        public int JointCount { get; }

        /// <summary>Values per motion line.</summary>
        public int ChannelCount { get; }

        /// <summary>
        /// Writes frame <paramref name="frame"/> of <paramref name="positions"/> (3 per joint) and
        /// <paramref name="rotations"/> (4 per joint, w x y z) from one motion line's values.
        /// </summary>
        public void ApplyRow(double[] row, int frame, double[] positions, double[] rotations)
        {
            // Locals, not fields, in the loop: the JIT keeps them in registers across the array stores.
            int jointCount = JointCount;
            bool[] hasPosition = _hasPosition, hasRotation = _hasRotation;
            int[] positionColumns = _positionColumns, rotationColumns = _rotationColumns;
            double[] offsets = _offsets;
            EulerOrder[] orders = _orders;
            int pBase = frame * jointCount * 3;
            int qBase = frame * jointCount * 4;
            for (int j = 0; j < jointCount; j++)
            {
                int p = pBase + 3 * j;
                if (hasPosition[j])
                {
                    positions[p] = row[positionColumns[3 * j]];
                    positions[p + 1] = row[positionColumns[3 * j + 1]];
                    positions[p + 2] = row[positionColumns[3 * j + 2]];
                }
                else
                {
                    positions[p] = offsets[3 * j];
                    positions[p + 1] = offsets[3 * j + 1];
                    positions[p + 2] = offsets[3 * j + 2];
                }

                QuaternionD q = hasRotation[j]
                    ? Quaternions.FromEulerDegrees(
                        row[rotationColumns[3 * j]],
                        row[rotationColumns[3 * j + 1]],
                        row[rotationColumns[3 * j + 2]],
                        orders[j])
                    : QuaternionD.Identity;
                int qi = qBase + 4 * j;
                rotations[qi] = q.W;
                rotations[qi + 1] = q.X;
                rotations[qi + 2] = q.Y;
                rotations[qi + 3] = q.Z;
            }
        }
    }
}
