using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// One joint of an imported BVH file as a transform of the skeleton prefab, in Unity's space
    /// (left-handed, Y up) and metres: its name, parent, path under the prefab's root (as curve bindings
    /// name it) and its rest local position and rotation.
    /// </summary>
    public sealed class ImportedJoint
    {
        internal ImportedJoint(string name, int parent, string path, Vector3D restPosition, QuaternionD restRotation, bool hasPositionCurves)
        {
            Name = name;
            Parent = parent;
            Path = path;
            RestPosition = restPosition;
            RestRotation = restRotation;
            HasPositionCurves = hasPositionCurves;
        }

        /// <summary>The joint's name in the file, which is the transform's name.</summary>
        public string Name { get; }

        /// <summary>Index of the parent joint, −1 for the root joint (a child of the prefab's root object).</summary>
        public int Parent { get; }

        /// <summary>Transform path relative to the prefab's root object, e.g. <c>Hips/Spine</c>.</summary>
        public string Path { get; }

        /// <summary>
        /// Rest local position, metres: the file's offset, and for the root joint its offset raised so that
        /// the lowest joint of the rest pose stands on the ground (y = 0).
        /// </summary>
        public Vector3D RestPosition { get; }

        /// <summary>
        /// Rest local rotation, (w, x, y, z): identity (the file's rest pose), or the humanoid T-pose
        /// (<see cref="HumanoidTPose"/>) when the file maps onto Unity's humanoid.
        /// </summary>
        public QuaternionD RestRotation { get; }

        /// <summary>True when the clip animates the joint's local position (the root, and any joint with position channels).</summary>
        public bool HasPositionCurves { get; }
    }
}
