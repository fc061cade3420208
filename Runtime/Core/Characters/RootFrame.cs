using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Characters
{
    /// <summary>
    /// Where a frame of reference sits in its parent's space: a position, a rotation (w, x, y, z) and a
    /// uniform scale, as a Unity <c>Transform</c> places its children (point in parent = position +
    /// rotation · (scale · point)). Used in Unity's space for the two frames around a character's root
    /// bone: its armature (the root bone's parent in the character, e.g. an FBX armature turned −90° about X
    /// and scaled 0.01) and the character itself in the world (the space root motion moves it through).
    /// </summary>
    /// <remarks>Unity allows non-uniform scale; a rig scaled non-uniformly cannot keep its bone directions
    /// under rotation, so <see cref="CharacterRig"/> refuses it and this type holds one scale.</remarks>
    public readonly struct RootFrame
    {
        /// <summary>Creates a frame.</summary>
        /// <exception cref="ArgumentOutOfRangeException">The scale is not a positive finite number.</exception>
        public RootFrame(Vector3D position, QuaternionD rotation, double scale)
        {
            if (!(scale > 0) || double.IsInfinity(scale)) throw new ArgumentOutOfRangeException(nameof(scale), scale, "expected a positive, finite uniform scale");
            Position = position;
            Rotation = Quaternions.Normalize(rotation);
            Scale = scale;
        }

        /// <summary>The frame that changes nothing.</summary>
        public static RootFrame Identity => new RootFrame(Vector3D.Zero, QuaternionD.Identity, 1.0);

        /// <summary>The frame's origin in its parent's space.</summary>
        public Vector3D Position { get; }

        /// <summary>The frame's rotation in its parent's space (w, x, y, z).</summary>
        public QuaternionD Rotation { get; }

        /// <summary>Parent units per frame unit.</summary>
        public double Scale { get; }

        /// <summary>A point given in this frame, in the parent's space.</summary>
        public Vector3D PointToParent(Vector3D point) => Position + Quaternions.Apply(Rotation, Scale * point);

        /// <summary>A point given in the parent's space, in this frame.</summary>
        public Vector3D PointFromParent(Vector3D point) => (1.0 / Scale) * Quaternions.Apply(Quaternions.Conjugate(Rotation), point - Position);

        /// <summary>A direction or displacement given in this frame, in the parent's space (no translation).</summary>
        public Vector3D VectorToParent(Vector3D vector) => Quaternions.Apply(Rotation, Scale * vector);

        /// <summary>A direction or displacement given in the parent's space, in this frame.</summary>
        public Vector3D VectorFromParent(Vector3D vector) => (1.0 / Scale) * Quaternions.Apply(Quaternions.Conjugate(Rotation), vector);

        /// <summary>A rotation given relative to this frame, relative to the parent.</summary>
        public QuaternionD RotationToParent(QuaternionD rotation) => Quaternions.Normalize(Quaternions.Multiply(Rotation, rotation));

        /// <summary>A rotation given relative to the parent, relative to this frame.</summary>
        public QuaternionD RotationFromParent(QuaternionD rotation) => Quaternions.Normalize(Quaternions.Multiply(Quaternions.Conjugate(Rotation), rotation));

        /// <summary>This frame's child <paramref name="child"/> (given in this frame), placed in this frame's parent.</summary>
        public RootFrame Then(RootFrame child) => new RootFrame(PointToParent(child.Position), RotationToParent(child.Rotation), Scale * child.Scale);

        /// <summary>The parent's placement in this frame (the inverse).</summary>
        public RootFrame Inverse()
        {
            QuaternionD back = Quaternions.Conjugate(Rotation);
            return new RootFrame((-1.0 / Scale) * Quaternions.Apply(back, Position), back, 1.0 / Scale);
        }
    }
}
