#nullable enable
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;
using UnityEngine;

namespace DeltaInterpolator.Editor.Humanoid
{
    /// <summary>
    /// Frame after frame of <c>HumanPoseHandler.GetHumanPose</c> (body position and rotation, every muscle) turned
    /// into a humanoid clip's curves by Core's <see cref="HumanoidCurves"/>: the one recording the baker's humanoid
    /// write-back and the BVH importer's humanoid clips share.
    /// </summary>
    internal sealed class HumanPoseRecording
    {
        private readonly string[] _muscleNames = HumanTrait.MuscleName;
        private readonly float[] _bodyPositions;
        private readonly float[] _bodyRotations;
        private readonly float[] _muscles;

        public HumanPoseRecording(int frames)
        {
            _bodyPositions = new float[3 * frames];
            _bodyRotations = new float[4 * frames];
            _muscles = new float[_muscleNames.Length * frames];
        }

        /// <summary>Stores <paramref name="pose"/> as frame <paramref name="frame"/>.</summary>
        public void Record(int frame, HumanPose pose)
        {
            _bodyPositions[3 * frame] = pose.bodyPosition.x;
            _bodyPositions[3 * frame + 1] = pose.bodyPosition.y;
            _bodyPositions[3 * frame + 2] = pose.bodyPosition.z;
            _bodyRotations[4 * frame] = pose.bodyRotation.x;
            _bodyRotations[4 * frame + 1] = pose.bodyRotation.y;
            _bodyRotations[4 * frame + 2] = pose.bodyRotation.z;
            _bodyRotations[4 * frame + 3] = pose.bodyRotation.w;
            Array.Copy(pose.muscles, 0, _muscles, frame * _muscleNames.Length, _muscleNames.Length);
        }

        /// <summary>The recorded frames as body and muscle curves, <paramref name="frameTime"/> seconds apart.</summary>
        public IReadOnlyList<ClipCurve> Curves(double frameTime) => HumanoidCurves.Build(_muscleNames, frameTime, _bodyPositions, _bodyRotations, _muscles);
    }
}
