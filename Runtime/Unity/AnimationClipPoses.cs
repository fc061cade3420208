using System;
using DeltaInterpolator.Core.Blends;
using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// An AnimationClip as Core's <see cref="IClipPoses"/>: the clip put on the character at a time with
    /// <c>AnimationClip.SampleAnimation</c> (through the Animator's avatar for a humanoid clip) and the rig's bones read
    /// back as a pose buffer. Sampling moves the bones: <see cref="NeuralBlendLayer"/> puts them back when it has read
    /// every key of a track.
    /// </summary>
    internal sealed class AnimationClipPoses : IClipPoses
    {
        private readonly AnimationClip _clip;
        private readonly GameObject _character;
        private readonly Transform[] _bones;

        public AnimationClipPoses(AnimationClip clip, GameObject character, Transform[] bones)
        {
            _clip = clip;
            _character = character;
            _bones = bones;
        }

        public string Name => _clip.name;

        public void Sample(double time, Span<double> rootPosition, Span<double> localRotations)
        {
            _clip.SampleAnimation(_character, (float)time);
            UnityPoses.Read(_bones, 0, rootPosition, localRotations);
        }
    }
}
