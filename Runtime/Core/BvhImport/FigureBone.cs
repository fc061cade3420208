using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// One visible piece of the skeleton prefab: a unit cube, child of <see cref="Joint"/>, stretched from
    /// that joint to one of its children (or End Sites) so that the figure shows where the bones are.
    /// Unity space, metres, local to the joint. Built by <see cref="BvhClipImport"/>.
    /// </summary>
    /// <param name="Joint">The joint (index into <see cref="BvhImportResult.Joints"/>) the piece hangs from.</param>
    /// <param name="Name">The piece's object name, unique in the prefab: <c>"LeftLeg bone"</c>, <c>"Head end"</c>.</param>
    /// <param name="LocalPosition">Local position: halfway along the bone.</param>
    /// <param name="LocalRotation">Local rotation, (w, x, y, z): the cube's +Y along the bone.</param>
    /// <param name="LocalScale">Local scale: the bone's thickness across, its length along +Y.</param>
    public sealed record FigureBone(int Joint, string Name, Vector3D LocalPosition, QuaternionD LocalRotation, Vector3D LocalScale);
}
