using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Rotations;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Animations;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// Core's <see cref="IPoseStream"/> on an <see cref="AnimationStream"/>: bone local rotations and the
    /// root bone's local position through transform stream handles. Only the component order changes here
    /// (Unity (x, y, z, w), Core (w, x, y, z)); the space stays Unity's, the joint map converts it.
    /// </summary>
    internal struct AnimatorPoseStream : IPoseStream
    {
        private readonly AnimationStream _stream;
        private readonly NativeArray<TransformStreamHandle> _bones;
        private readonly int _rootBone;

        public AnimatorPoseStream(AnimationStream stream, NativeArray<TransformStreamHandle> bones, int rootBone)
        {
            _stream = stream;
            _bones = bones;
            _rootBone = rootBone;
        }

        public int BoneCount => _bones.Length;

        public Vector3D ReadRootPosition()
        {
            Vector3 p = _bones[_rootBone].GetLocalPosition(_stream);
            return new Vector3D(p.x, p.y, p.z);
        }

        public void WriteRootPosition(Vector3D position)
        {
            _bones[_rootBone].SetLocalPosition(_stream, new Vector3((float)position.X, (float)position.Y, (float)position.Z));
        }

        public QuaternionD ReadLocalRotation(int bone)
        {
            Quaternion q = _bones[bone].GetLocalRotation(_stream);
            return new QuaternionD(q.w, q.x, q.y, q.z);
        }

        public void WriteLocalRotation(int bone, QuaternionD rotation)
        {
            _bones[bone].SetLocalRotation(_stream, new Quaternion((float)rotation.X, (float)rotation.Y, (float)rotation.Z, (float)rotation.W));
        }
    }
}
