using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// One joint of an imported BVH file as a transform of the skeleton prefab, in Unity's space
    /// (left-handed, Y up) and metres: its name, parent, path under the prefab's root (as curve bindings
    /// name it) and its rest local position and rotation. Built by <see cref="BvhClipImport"/>.
    /// </summary>
    /// <param name="Name">The joint's name in the file, which is the transform's name.</param>
    /// <param name="Parent">Index of the parent joint, −1 for the root joint (a child of the prefab's root object).</param>
    /// <param name="Path">Transform path relative to the prefab's root object, e.g. <c>Hips/Spine</c>.</param>
    /// <param name="RestPosition">
    /// Rest local position, metres: the file's offset, and for the root joint its offset raised so that
    /// the lowest joint of the rest pose stands on the ground (y = 0).
    /// </param>
    /// <param name="RestRotation">
    /// Rest local rotation, (w, x, y, z): identity (the file's rest pose), or the humanoid T-pose
    /// (<see cref="HumanoidTPose"/>) when the file maps onto Unity's humanoid.
    /// </param>
    /// <param name="HasPositionCurves">True when the clip animates the joint's local position (the root, and any joint with position channels).</param>
    public sealed record ImportedJoint(string Name, int Parent, string Path, Vector3D RestPosition, QuaternionD RestRotation, bool HasPositionCurves);
}
