using System;

namespace DeltaInterpolator.Core.Characters
{
    /// <summary>
    /// Converts poses between a character (its bones, in Unity's space: left-handed, Y up, metres) and the
    /// model (its joints, in the model's space: right-handed, Y up, data units), both ways. A pose is a root
    /// position (3 values) and one local rotation (w, x, y, z) per bone or joint, in flat arrays.
    /// </summary>
    /// <remarks>
    /// <see cref="NamePoseConverter"/> matches bones to joints by name for characters that share the model's
    /// skeleton; a retargeting map (different rest poses and bone names) implements the same interface.
    /// Implementations must not allocate: the player calls them every frame.
    /// </remarks>
    public interface IPoseConverter
    {
        /// <summary>Number of character bones the map reads and drives.</summary>
        int BoneCount { get; }

        /// <summary>Number of model joints, the contract's joint count.</summary>
        int JointCount { get; }

        /// <summary>A character pose (root 3, rotations <see cref="BoneCount"/> × 4) → a model pose (root 3, rotations <see cref="JointCount"/> × 4).</summary>
        void ToModel(ReadOnlySpan<double> boneRoot, ReadOnlySpan<double> boneRotations, Span<double> jointRoot, Span<double> jointRotations);

        /// <summary>A model pose (root 3, rotations <see cref="JointCount"/> × 4) → a character pose (root 3, rotations <see cref="BoneCount"/> × 4).</summary>
        void ToCharacter(ReadOnlySpan<double> jointRoot, ReadOnlySpan<double> jointRotations, Span<double> boneRoot, Span<double> boneRotations);
    }
}
