using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Characters
{
    /// <summary>
    /// An <see cref="IPoseConverter"/> for characters whose skeleton is not the model's (e.g. a Unity humanoid
    /// rig): a <see cref="SkeletonMap"/> from the character's skeleton (its bone names, hierarchy, rest
    /// offsets and reference pose) to the model's, with a <see cref="JointMap"/> such as
    /// <see cref="JointMap.UnityHumanoid"/>. Bones pointing the same way in the world on both sides is
    /// what is kept, so rest poses and bone names may differ; the root's position is scaled by the leg
    /// lengths (<see cref="SkeletonMap.RootScale"/>), which also converts metres to the model's units.
    /// </summary>
    /// <remarks>
    /// Bones no model joint maps to keep, on the way back, the rotation they had in the last pose given to
    /// <see cref="ToModel"/> (the character's own animation). A character pose is what the animation stream
    /// holds: the root bone's position and rotation are local to its parent (<see cref="Armature"/>, e.g. an
    /// FBX armature turned and scaled), the other bones' rotations local to theirs. Allocation-free after
    /// construction; one thread at a time.
    /// </remarks>
    public sealed class SkeletonPoseConverter : IPoseConverter
    {
        private readonly double[] _positions;
        private readonly double[] _readRotations;
        private readonly double[] _backPositions;
        private readonly double[] _backRotations;

        /// <summary>Wraps <paramref name="map"/>, whose source is the character (model handedness) and target the model.</summary>
        public SkeletonPoseConverter(SkeletonMap map)
            : this(map, RootFrame.Identity)
        {
        }

        /// <summary>
        /// Wraps <paramref name="map"/>, whose source is the character in its own space (model handedness), with
        /// the root bone's parent placed in the character's space (Unity's) by <paramref name="armature"/>.
        /// </summary>
        public SkeletonPoseConverter(SkeletonMap map, RootFrame armature)
        {
            Map = map ?? throw new ArgumentNullException(nameof(map));
            Armature = armature;
            int n = map.Source.JointCount;
            _positions = new double[3 * n];
            for (int i = 0; i < _positions.Length; i++) _positions[i] = map.Source.Offsets[i];
            _readRotations = new double[4 * n];
            _backPositions = new double[3 * n];
            _backRotations = new double[4 * n];
            // Until the first ToModel, unmapped bones come back in the reference pose.
            for (int i = 0; i < _readRotations.Length; i++) _readRotations[i] = map.SourceReference.LocalRotations[i];
        }

        /// <summary>The retargeting map (source: the character, target: the model).</summary>
        public SkeletonMap Map { get; }

        /// <summary>The root bone's parent in the character's space (Unity's); identity when the root bone sits directly under the character.</summary>
        public RootFrame Armature { get; }

        /// <inheritdoc />
        public int BoneCount => Map.Source.JointCount;

        /// <inheritdoc />
        public int JointCount => Map.Target.JointCount;

        /// <summary>
        /// Builds the map of a character given in Unity's space (left-handed, metres): each bone's name,
        /// parent (−1 for the root; parents before children), local position and reference local rotation
        /// (w, x, y, z, as everywhere in Core), mapped onto
        /// <paramref name="model"/> with <paramref name="jointMap"/> (default <see cref="JointMap.UnityHumanoid"/>).
        /// </summary>
        /// <param name="boneNames">The character's bone names (for a humanoid: <c>HumanBodyBones</c> names).</param>
        /// <param name="parents">Each bone's parent index, −1 for the root.</param>
        /// <param name="unityLocalPositions">Bones × 3 local positions in Unity's space (the rest pose).</param>
        /// <param name="unityReferenceRotations">Bones × 4 local rotations (w, x, y, z) in Unity's space of a T-pose-like reference.</param>
        /// <param name="model">The model's skeleton (the contract's).</param>
        /// <param name="source">The character's name for messages.</param>
        /// <param name="jointMap">Model joint → character bone chains; null: <see cref="JointMap.UnityHumanoid"/>.</param>
        /// <exception cref="JointMapException">A model joint has no bone.</exception>
        public static SkeletonPoseConverter FromUnity(IReadOnlyList<string> boneNames, IReadOnlyList<int> parents, IReadOnlyList<double> unityLocalPositions,
            IReadOnlyList<double> unityReferenceRotations, Skeleton model, string source, JointMap? jointMap = null)
        {
            if (boneNames == null) throw new ArgumentNullException(nameof(boneNames));
            int n = boneNames.Count;
            if (parents.Count != n || unityLocalPositions.Count != 3 * n || unityReferenceRotations.Count != 4 * n)
            {
                throw new ArgumentException($"{source}: {n} bones need {n} parents, {3 * n} positions and {4 * n} rotations");
            }

            var offsets = new double[3 * n];
            var rotations = new double[4 * n];
            for (int b = 0; b < n; b++)
            {
                Handedness.PositionFromUnity(new Vector3D(unityLocalPositions[3 * b], unityLocalPositions[3 * b + 1], unityLocalPositions[3 * b + 2])).Write(offsets, 3 * b);
                Handedness.RotationFromUnity(new QuaternionD(unityReferenceRotations[4 * b], unityReferenceRotations[4 * b + 1], unityReferenceRotations[4 * b + 2], unityReferenceRotations[4 * b + 3])).Write(rotations, 4 * b);
            }

            var skeleton = new Skeleton(boneNames, parents, offsets);
            var reference = new ReferencePose(skeleton, rotations, Vector3D.Read(offsets, 0));
            return new SkeletonPoseConverter(SkeletonMap.Create(reference, ReferencePose.ModelTPose(model), jointMap ?? JointMap.UnityHumanoid, source));
        }

        /// <inheritdoc />
        public void ToModel(ReadOnlySpan<double> boneRoot, ReadOnlySpan<double> boneRotations, Span<double> jointRoot, Span<double> jointRotations)
        {
            Handedness.PositionFromUnity(Armature.PointToParent(Vector3D.Read(boneRoot, 0))).Write(_positions, 0);
            Handedness.RotationFromUnity(Armature.RotationToParent(QuaternionD.Read(boneRotations, 0))).Write(_readRotations, 0);
            for (int b = 1; b < BoneCount; b++)
            {
                Handedness.RotationFromUnity(QuaternionD.Read(boneRotations, 4 * b)).Write(_readRotations, 4 * b);
            }

            Map.ToTargetFrame(_positions, _readRotations, jointRoot, jointRotations);
        }

        /// <inheritdoc />
        public void ToCharacter(ReadOnlySpan<double> jointRoot, ReadOnlySpan<double> jointRotations, Span<double> boneRoot, Span<double> boneRotations)
        {
            _positions.AsSpan().CopyTo(_backPositions);
            _readRotations.AsSpan().CopyTo(_backRotations);
            Map.ToSourceFrame(Vector3D.Read(jointRoot, 0), jointRotations, _backPositions, _backRotations);
            Armature.PointFromParent(Handedness.PositionToUnity(Vector3D.Read(_backPositions, 0))).Write(boneRoot, 0);
            Armature.RotationFromParent(Handedness.RotationToUnity(QuaternionD.Read(_backRotations, 0))).Write(boneRotations, 0);
            for (int b = 1; b < BoneCount; b++)
            {
                Handedness.RotationToUnity(QuaternionD.Read(_backRotations, 4 * b)).Write(boneRotations, 4 * b);
            }
        }
    }
}
