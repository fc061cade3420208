using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Characters
{
    /// <summary>
    /// The simplest <see cref="IPoseConverter"/>: each character bone is the model joint of the same name, with
    /// the same rest pose. Only the space changes: <see cref="Handedness"/> (mirror X) and the unit scale
    /// (model data units × <see cref="UnitScale"/> = metres). Right for a character imported from
    /// the model's own skeleton (e.g. a LaFAN1 BVH or FBX); characters with other skeletons need a
    /// retargeting map.
    /// </summary>
    public sealed class NamePoseConverter : IPoseConverter
    {
        private readonly int[] _boneOfJoint;
        private readonly double _unitScale;

        /// <summary>Maps <paramref name="boneNames"/> (the character's bones, in stream order) onto the model's joints.</summary>
        /// <param name="model">The model's skeleton (<c>ModelContract.Skeleton</c>).</param>
        /// <param name="unitScale">Metres per model data unit (<c>ModelContract.UnitScale</c>; LaFAN1: 0.01).</param>
        /// <param name="boneNames">One name per driven bone; together exactly the model's joint names, in any order.</param>
        /// <exception cref="ArgumentException">A name is unknown, repeated or missing; the message lists them.</exception>
        public NamePoseConverter(Skeleton model, double unitScale, IReadOnlyList<string> boneNames)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            if (boneNames == null) throw new ArgumentNullException(nameof(boneNames));
            if (!(unitScale > 0) || double.IsInfinity(unitScale)) throw new ArgumentOutOfRangeException(nameof(unitScale), unitScale, "expected a positive unit scale");
            _unitScale = unitScale;
            _boneOfJoint = new int[model.JointCount];
            for (int j = 0; j < _boneOfJoint.Length; j++) _boneOfJoint[j] = -1;
            var unknown = new List<string>();
            for (int b = 0; b < boneNames.Count; b++)
            {
                int j = model.IndexOf(boneNames[b]);
                if (j < 0)
                {
                    unknown.Add(boneNames[b]);
                    continue;
                }

                if (_boneOfJoint[j] >= 0) throw new ArgumentException($"bone '{boneNames[b]}' is listed twice (bones {_boneOfJoint[j]} and {b}); list each model joint once", nameof(boneNames));
                _boneOfJoint[j] = b;
            }

            var missing = new List<string>();
            for (int j = 0; j < _boneOfJoint.Length; j++)
            {
                if (_boneOfJoint[j] < 0) missing.Add(model.Names[j]);
            }

            if (unknown.Count > 0 || missing.Count > 0)
            {
                throw new ArgumentException(
                    $"the character's bones do not match the model's joints by name (not in the model: {List(unknown)}; missing: {List(missing)}); " +
                    "name the bones like the model's joints or use a retargeting joint map", nameof(boneNames));
            }

            BoneCount = boneNames.Count;
            RootBone = _boneOfJoint[0];
        }

        /// <inheritdoc />
        public int BoneCount { get; }

        /// <inheritdoc />
        public int JointCount => _boneOfJoint.Length;

        /// <summary>The bone that is the model's root joint (its position is the pose's root position).</summary>
        public int RootBone { get; }

        /// <summary>Metres per model data unit.</summary>
        public double UnitScale => _unitScale;

        /// <summary>The bone that model joint <paramref name="joint"/> maps to.</summary>
        public int BoneOf(int joint) => _boneOfJoint[joint];

        /// <inheritdoc />
        public void ToModel(ReadOnlySpan<double> boneRoot, ReadOnlySpan<double> boneRotations, Span<double> jointRoot, Span<double> jointRotations)
        {
            Vector3D root = Handedness.PositionFromUnity(Vector3D.Read(boneRoot, 0));
            ((1.0 / _unitScale) * root).Write(jointRoot, 0);
            for (int j = 0; j < _boneOfJoint.Length; j++)
            {
                Handedness.RotationFromUnity(QuaternionD.Read(boneRotations, 4 * _boneOfJoint[j])).Write(jointRotations, 4 * j);
            }
        }

        /// <inheritdoc />
        public void ToCharacter(ReadOnlySpan<double> jointRoot, ReadOnlySpan<double> jointRotations, Span<double> boneRoot, Span<double> boneRotations)
        {
            Handedness.PositionToUnity(_unitScale * Vector3D.Read(jointRoot, 0)).Write(boneRoot, 0);
            for (int j = 0; j < _boneOfJoint.Length; j++)
            {
                Handedness.RotationToUnity(QuaternionD.Read(jointRotations, 4 * j)).Write(boneRotations, 4 * _boneOfJoint[j]);
            }
        }

        private static string List(List<string> names) => names.Count == 0 ? "none" : string.Join(", ", names);
    }
}
