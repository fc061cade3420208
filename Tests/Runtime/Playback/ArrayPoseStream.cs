using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>An <see cref="IPoseStream"/> over arrays: what an animation stream holds in a simulated frame loop.</summary>
    public struct ArrayPoseStream : IPoseStream
    {
        public ArrayPoseStream(double[] root, double[] rotations)
        {
            Root = root;
            Rotations = rotations;
        }

        public double[] Root { get; }

        public double[] Rotations { get; }

        public int BoneCount => Rotations.Length / 4;

        public Vector3D ReadRootPosition() => Vector3D.Read(Root, 0);

        public void WriteRootPosition(Vector3D position) => position.Write(Root, 0);

        public QuaternionD ReadLocalRotation(int bone) => QuaternionD.Read(Rotations, 4 * bone);

        public void WriteLocalRotation(int bone, QuaternionD rotation) => rotation.Write(Rotations, 4 * bone);
    }
}
