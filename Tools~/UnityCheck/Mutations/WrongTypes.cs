// Must NOT compile: calls stubbed members with the wrong types (TransformStreamHandle.SetLocalRotation
// takes a UnityEngine.Quaternion, PlayableGraph.Create a string). `Tools~/UnityCheck/check` expects CS1503.
using UnityEngine.Animations;
using UnityEngine.Playables;

namespace DeltaInterpolator.Unity.MustFail
{
    internal static class WrongTypes
    {
        public static void Call(TransformStreamHandle handle, AnimationStream stream)
        {
            handle.SetLocalRotation(stream, new UnityEngine.Vector3(0, 0, 0));
            PlayableGraph.Create(42);
        }
    }
}
