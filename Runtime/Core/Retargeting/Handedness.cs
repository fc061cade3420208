using System.Runtime.CompilerServices;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// The one conversion between the model's space (right-handed, Y up, as BVH) and Unity's (left-handed,
    /// Y up): a mirror of the X axis, as Unity's own FBX importer does. For a mirror S = diag(-1, 1, 1) a
    /// rotation R becomes S·R·S, which for a quaternion (w, x, y, z) is (w, x, -y, -z): the rotation axis is
    /// mirrored like a position and the angle changes sign. Each pair below is its own inverse; callers use
    /// the named direction so that the boundary reads clearly. Component order ((w, x, y, z) here,
    /// (x, y, z, w) in <c>UnityEngine.Quaternion</c>) is converted by the Unity glue, not here.
    /// </summary>
    public static class Handedness
    {
        /// <summary>A position (or direction) in model space → Unity space.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D PositionToUnity(Vector3D modelPosition) => new Vector3D(-modelPosition.X, modelPosition.Y, modelPosition.Z);

        /// <summary>A position (or direction) in Unity space → model space.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D PositionFromUnity(Vector3D unityPosition) => new Vector3D(-unityPosition.X, unityPosition.Y, unityPosition.Z);

        /// <summary>A rotation in model space → Unity space.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static QuaternionD RotationToUnity(QuaternionD modelRotation) => new QuaternionD(modelRotation.W, modelRotation.X, -modelRotation.Y, -modelRotation.Z);

        /// <summary>A rotation in Unity space → model space.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static QuaternionD RotationFromUnity(QuaternionD unityRotation) => new QuaternionD(unityRotation.W, unityRotation.X, -unityRotation.Y, -unityRotation.Z);
    }
}
