using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// One visible piece of the skeleton prefab: a unit cube, child of <see cref="Joint"/>, stretched from
    /// that joint to one of its children (or End Sites) so that the figure shows where the bones are.
    /// Unity space, metres, local to the joint.
    /// </summary>
    public sealed class FigureBone
    {
        internal FigureBone(int joint, string name, Vector3D localPosition, QuaternionD localRotation, Vector3D localScale)
        {
            Joint = joint;
            Name = name;
            LocalPosition = localPosition;
            LocalRotation = localRotation;
            LocalScale = localScale;
        }

        /// <summary>The joint (index into <see cref="BvhImportResult.Joints"/>) the piece hangs from.</summary>
        public int Joint { get; }

        /// <summary>The piece's object name, unique in the prefab: <c>"LeftLeg bone"</c>, <c>"Head end"</c>.</summary>
        public string Name { get; }

        /// <summary>Local position: halfway along the bone.</summary>
        public Vector3D LocalPosition { get; }

        /// <summary>Local rotation, (w, x, y, z): the cube's +Y along the bone.</summary>
        public QuaternionD LocalRotation { get; }

        /// <summary>Local scale: the bone's thickness across, its length along +Y.</summary>
        public Vector3D LocalScale { get; }
    }
}
