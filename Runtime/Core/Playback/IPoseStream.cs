using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Playback
{
    /// <summary>
    /// The character's pose as the animation system holds it during one evaluation: the root bone's
    /// position and every driven bone's local rotation, in the character's space (Unity: left-handed,
    /// Y up, metres; quaternions (w, x, y, z)). Reading gives what the layers before this one produced
    /// (the user's Animator Controller); writing replaces it with the pose to show.
    /// </summary>
    /// <remarks>
    /// Bones are numbered as the <see cref="Characters.IPoseConverter"/> numbers them. The Unity glue implements this on
    /// an <c>AnimationStream</c> with transform stream handles; tests and benchmarks implement it on
    /// arrays. Implemented by structs and used through generic constraints, so no call boxes or allocates.
    /// </remarks>
    public interface IPoseStream
    {
        /// <summary>Number of bones, <see cref="Characters.IPoseConverter.BoneCount"/>.</summary>
        int BoneCount { get; }

        /// <summary>The root bone's position in the character's space.</summary>
        Vector3D ReadRootPosition();

        /// <summary>Sets the root bone's position in the character's space.</summary>
        void WriteRootPosition(Vector3D position);

        /// <summary>The local rotation of bone <paramref name="bone"/>.</summary>
        QuaternionD ReadLocalRotation(int bone);

        /// <summary>Sets the local rotation of bone <paramref name="bone"/>.</summary>
        void WriteLocalRotation(int bone, QuaternionD rotation);
    }
}
