using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>
    /// A character's pose in two plain arrays, read and written as the Animator's stream would be: what the
    /// crowd benchmark plays instead of a rig. A struct, so stepping a crowd allocates nothing.
    /// </summary>
    internal struct ArrayPoseStream : IPoseStream
    {
        private readonly double[] _root;
        private readonly double[] _rotations;

        public ArrayPoseStream(double[] root, double[] rotations)
        {
            _root = root;
            _rotations = rotations;
        }

        public int BoneCount => _rotations.Length / 4;

        public Vector3D ReadRootPosition() => Vector3D.Read(_root, 0);

        public void WriteRootPosition(Vector3D position) => position.Write(_root, 0);

        public QuaternionD ReadLocalRotation(int bone) => QuaternionD.Read(_rotations, 4 * bone);

        public void WriteLocalRotation(int bone, QuaternionD rotation) => rotation.Write(_rotations, 4 * bone);
    }
}
