using System;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// Where a character's root stands on the ground and which way it faces: a position on the ground plane (Unity's x
    /// and z) and a yaw about +Y in radians (0 faces +Z, as Unity characters are authored). What root motion moves: the
    /// engine extracts a root node's (generic) or the body's (humanoid) travel as a ground position and a turn about the
    /// up axis. Used both as a placement and as a step from one placement to the next (in the first one's frame).
    /// </summary>
    public readonly struct RootPlacement
    {
        /// <summary>A placement (or a step).</summary>
        public RootPlacement(double x, double z, double yaw)
        {
            X = x;
            Z = z;
            Yaw = yaw;
        }

        /// <summary>An angle in radians brought into −π..π (the same facing): the one rule for comparing and unwrapping yaws.</summary>
        public static double WrapYaw(double angle) => Math.IEEERemainder(angle, 2 * Math.PI);

        /// <summary>Whether the position and yaw are all finite numbers.</summary>
        public bool IsFinite => double.IsFinite(X) && double.IsFinite(Z) && double.IsFinite(Yaw);

        /// <summary>The origin, facing +Z.</summary>
        public static RootPlacement Identity => new RootPlacement(0, 0, 0);

        /// <summary>Position along x.</summary>
        public double X { get; }

        /// <summary>Position along z.</summary>
        public double Z { get; }

        /// <summary>Turn about +Y, radians (a rotation by it carries +Z to (sin yaw, 0, cos yaw)).</summary>
        public double Yaw { get; }

        /// <summary>This placement moved on by <paramref name="step"/>, a step in this placement's own frame.</summary>
        public RootPlacement Then(RootPlacement step)
        {
            double c = Math.Cos(Yaw), s = Math.Sin(Yaw);
            return new RootPlacement(X + c * step.X + s * step.Z, Z - s * step.X + c * step.Z, Yaw + step.Yaw);
        }

        /// <summary>The step, in this placement's frame, that leads to <paramref name="other"/>: <c>Then(StepTo(other))</c> is <paramref name="other"/>.</summary>
        public RootPlacement StepTo(RootPlacement other)
        {
            double c = Math.Cos(Yaw), s = Math.Sin(Yaw), dx = other.X - X, dz = other.Z - Z;
            return new RootPlacement(c * dx - s * dz, s * dx + c * dz, other.Yaw - Yaw);
        }

        /// <summary>The placement that undoes this one.</summary>
        public RootPlacement Inverse() => StepTo(Identity);

        /// <summary>
        /// The root placement of a pose of <paramref name="rig"/>: its root bone's position on the ground and its facing — the
        /// root bone's rotation relative to the rig's reference pose, applied to +Z and projected on the ground — both in the
        /// character's frame (through the rig's armature). A root pointing straight up or down faces 0.
        /// </summary>
        /// <param name="rig">The character.</param>
        /// <param name="rootPosition">The root bone's local position (3 values, as a pose buffer holds it).</param>
        /// <param name="rootRotation">The root bone's local rotation (w, x, y, z).</param>
        public static RootPlacement OfPose(CharacterRig rig, ReadOnlySpan<double> rootPosition, ReadOnlySpan<double> rootRotation)
        {
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            RootFrame armature = rig.Armature;
            Vector3D position = armature.PointToParent(Vector3D.Read(rootPosition, 0));
            QuaternionD reference = new QuaternionD(rig.ReferenceRotations[0], rig.ReferenceRotations[1], rig.ReferenceRotations[2], rig.ReferenceRotations[3]);
            QuaternionD turned = Quaternions.Multiply(armature.RotationToParent(QuaternionD.Read(rootRotation, 0)), Quaternions.Conjugate(armature.RotationToParent(reference)));
            Vector3D facing = Quaternions.Apply(turned, new Vector3D(0, 0, 1));
            double yaw = facing.X * facing.X + facing.Z * facing.Z < 1e-12 ? 0 : Math.Atan2(facing.X, facing.Z);
            return new RootPlacement(position.X, position.Z, yaw);
        }

        /// <summary>
        /// Where an object stands on the ground given its position and rotation in its parent's space (Unity's
        /// <c>Transform.localPosition</c>, <c>localRotation</c>): its x and z, and its facing — the rotation applied to +Z,
        /// projected on the ground (an object facing straight up or down faces 0). Height, pitch and roll are not kept.
        /// </summary>
        /// <param name="x">Position along x.</param>
        /// <param name="z">Position along z.</param>
        /// <param name="rotation">The rotation (w, x, y, z; normalised or not).</param>
        public static RootPlacement OfTransform(double x, double z, QuaternionD rotation)
        {
            Vector3D facing = Quaternions.Apply(rotation, new Vector3D(0, 0, 1));
            double yaw = facing.X * facing.X + facing.Z * facing.Z < 1e-12 ? 0 : Math.Atan2(facing.X, facing.Z);
            return new RootPlacement(x, z, yaw);
        }

        /// <summary>
        /// <paramref name="rotation"/> turned about +Y (in its parent's space) until it faces <paramref name="yaw"/> as
        /// <see cref="OfTransform"/> reads facings, its pitch and roll kept: what puts an object's rotation at a placement
        /// directly, where a frame has no time to turn it by a turn rate (a paused Editor preview). An object facing straight
        /// up or down (facing 0, as <see cref="OfTransform"/> reads it) is turned by the whole yaw.
        /// </summary>
        public static QuaternionD TurnedTo(QuaternionD rotation, double yaw)
        {
            double turn = yaw - OfTransform(0, 0, rotation).Yaw;
            return Quaternions.Multiply(new QuaternionD(Math.Cos(turn / 2), 0, Math.Sin(turn / 2), 0), rotation);
        }

        /// <summary>
        /// A Timeline offset — an Animation Track's or a clip's position and Euler angles (degrees, Unity's Z-X-Y order,
        /// <c>Quaternion.Euler</c>) — as a placement on the ground: its x and z, and the yaw its rotation faces
        /// (the rotation applied to +Z, projected on the ground). A height or a pitch or roll cannot be a placement on the
        /// ground: they are left out and <paramref name="flattened"/> says so (the caller says it once).
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException">A value that is not finite (the parameter named).</exception>
        public static RootPlacement OfOffset(double x, double y, double z, double pitch, double yaw, double roll, out bool flattened)
        {
            Finite(x, nameof(x));
            Finite(y, nameof(y));
            Finite(z, nameof(z));
            Finite(pitch, nameof(pitch));
            Finite(yaw, nameof(yaw));
            Finite(roll, nameof(roll));
            // Unity's Euler rotation is Y·X·Z: Z (roll) leaves +Z where it is, X (pitch) tips it to (0, −sin p, cos p), Y turns
            // that about +Y: its ground direction is cos p · (sin y, cos y), the yaw itself unless the pitch turns it over.
            double p = pitch * Math.PI / 180, w = yaw * Math.PI / 180, c = Math.Cos(p);
            double facing = Math.Abs(c) < 1e-9 ? w : c > 0 ? w : w + Math.PI;
            flattened = y != 0 || Math.IEEERemainder(pitch, 360) != 0 || Math.IEEERemainder(roll, 360) != 0;
            return new RootPlacement(x, z, facing);
        }

        /// <summary>
        /// Moves a pose of <paramref name="rig"/> by this placement taken as a motion of the ground: its root bone's position
        /// turned by <see cref="Yaw"/> about the character's origin and moved by (<see cref="X"/>, <see cref="Z"/>), its
        /// rotation turned by <see cref="Yaw"/>; height and every other bone unchanged. Allocation-free.
        /// </summary>
        public void Move(CharacterRig rig, Span<double> rootPosition, Span<double> rootRotation)
        {
            RootFrame armature = rig.Armature;
            Vector3D p = armature.PointToParent(Vector3D.Read(rootPosition, 0));
            double c = Math.Cos(Yaw), s = Math.Sin(Yaw);
            armature.PointFromParent(new Vector3D(X + c * p.X + s * p.Z, p.Y, Z - s * p.X + c * p.Z)).Write(rootPosition, 0);
            QuaternionD turn = new QuaternionD(Math.Cos(Yaw / 2), 0, Math.Sin(Yaw / 2), 0);
            QuaternionD q = Quaternions.Multiply(turn, armature.RotationToParent(QuaternionD.Read(rootRotation, 0)));
            armature.RotationFromParent(q).Write(rootRotation, 0);
        }

        /// <summary>Refuses a placement that is not finite, naming the parameter <paramref name="name"/>.</summary>
        /// <exception cref="ArgumentOutOfRangeException">A position or yaw that is not finite.</exception>
        internal static void RequireFinite(RootPlacement placement, string name)
        {
            if (!placement.IsFinite) throw new ArgumentOutOfRangeException(name, placement.ToString(), "expected a finite position and yaw");
        }

        private static void Finite(double value, string name)
        {
            if (!double.IsFinite(value)) throw new ArgumentOutOfRangeException(name, value, "expected a finite offset (a position in units, an angle in degrees)");
        }

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant($"({X:0.####}, {Z:0.####}, {Yaw * 180 / Math.PI:0.##}°)");
    }
}
