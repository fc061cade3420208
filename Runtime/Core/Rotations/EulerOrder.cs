using System;

namespace DeltaInterpolator.Core.Rotations
{
    /// <summary>
    /// The order in which three Euler angles are composed, named by their axes in the order the values
    /// appear (as in a BVH CHANNELS line). Composition is intrinsic: for <see cref="Zyx"/> the angles
    /// (a, b, c) give q = q_z(a) ⊗ q_y(b) ⊗ q_x(c), i.e. R = R_z(a)·R_y(b)·R_x(c) acting on column
    /// vectors — the convention of the official LaFAN1 code and of BVH.
    /// </summary>
    public enum EulerOrder
    {
        /// <summary>X, then Y, then Z.</summary>
        Xyz,
        /// <summary>X, then Z, then Y.</summary>
        Xzy,
        /// <summary>Y, then X, then Z.</summary>
        Yxz,
        /// <summary>Y, then Z, then X.</summary>
        Yzx,
        /// <summary>Z, then X, then Y.</summary>
        Zxy,
        /// <summary>Z, then Y, then X (LaFAN1).</summary>
        Zyx,
    }

    /// <summary>Axis look-ups for <see cref="EulerOrder"/>.</summary>
    internal static class EulerOrders
    {
        /// <summary>All six orders.</summary>
        public static readonly EulerOrder[] All =
        {
            EulerOrder.Xyz, EulerOrder.Xzy, EulerOrder.Yxz, EulerOrder.Yzx, EulerOrder.Zxy, EulerOrder.Zyx,
        };

        /// <summary>The axis (0 = X, 1 = Y, 2 = Z) of the angle at <paramref name="position"/> (0..2).</summary>
        public static int Axis(this EulerOrder order, int position)
        {
            if (position < 0 || position > 2)
            {
                throw new ArgumentOutOfRangeException(nameof(position), "position must be 0, 1 or 2");
            }

            switch (order)
            {
                case EulerOrder.Xyz: return position == 0 ? 0 : position == 1 ? 1 : 2;
                case EulerOrder.Xzy: return position == 0 ? 0 : position == 1 ? 2 : 1;
                case EulerOrder.Yxz: return position == 0 ? 1 : position == 1 ? 0 : 2;
                case EulerOrder.Yzx: return position == 0 ? 1 : position == 1 ? 2 : 0;
                case EulerOrder.Zxy: return position == 0 ? 2 : position == 1 ? 0 : 1;
                case EulerOrder.Zyx: return position == 0 ? 2 : position == 1 ? 1 : 0;
                default: throw new ArgumentOutOfRangeException(nameof(order), order, "unknown Euler order");
            }
        }

        /// <summary>The order whose axes are <paramref name="first"/>, <paramref name="second"/>, <paramref name="third"/> (0 = X, 1 = Y, 2 = Z).</summary>
        /// <exception cref="ArgumentException">The axes are not a permutation of X, Y, Z.</exception>
        public static EulerOrder FromAxes(int first, int second, int third)
        {
            foreach (EulerOrder order in All)
            {
                if (order.Axis(0) == first && order.Axis(1) == second && order.Axis(2) == third)
                {
                    return order;
                }
            }

            throw new ArgumentException(FormattableString.Invariant(
                $"axes ({first}, {second}, {third}) are not a permutation of X, Y, Z"));
        }
    }
}
