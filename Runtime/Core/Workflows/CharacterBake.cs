using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// The editor baker's Core path: a character's key poses as the component sees the character (its
    /// <see cref="CharacterRig"/>, the joint map with the settings' renames) → <see cref="InbetweenBake.Run"/>
    /// through the same skeleton map as the component (<see cref="CharacterRig.CreatePoseConverter"/>: reference pose
    /// checked against the model's T-pose) → the filled motion on the character's skeleton, which
    /// <see cref="CharacterPoseTrack.ReadUnityPose"/> turns back into the bones' local transforms.
    /// </summary>
    public static class CharacterBake
    {
        /// <summary>How <paramref name="rig"/>'s motion reaches the model: the component's map, at <paramref name="frameTime"/> seconds per rig frame.</summary>
        /// <param name="contract">The model's contract (skeleton, frame rate).</param>
        /// <param name="rig">The character as the Unity layer collected it.</param>
        /// <param name="jointMap">Model joint → bone chains (the settings' map with its renames); null: the built-in map that finds the most bones.</param>
        /// <param name="frameTime">Seconds per frame of the character's track.</param>
        /// <param name="maxBoneDeviationDegrees">How far a mapped bone of the reference pose may point from the model's T-pose.</param>
        /// <exception cref="JointMapException">A model joint has no bone, or the reference pose is not a T-pose (bones named).</exception>
        public static MappedRig Retargeting(ModelContract contract, CharacterRig rig, JointMap? jointMap, double frameTime, double maxBoneDeviationDegrees = CharacterRig.DefaultMaxBoneDeviationDegrees)
        {
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            if (rig == null) throw new ArgumentNullException(nameof(rig));
            SkeletonPoseConverter map = rig.CreatePoseConverter(contract.Skeleton, jointMap, maxBoneDeviationDegrees);
            return MappedRig.FromMap(contract, map.Map, frameTime, rig.Name, "the character's reference pose");
        }

        /// <summary>
        /// Fills the gaps between <paramref name="track"/>'s key frames with each of <paramref name="methods"/>.
        /// Each result's <see cref="MethodBake.OnRig"/> spans the track's first to last key, on the character's skeleton.
        /// </summary>
        /// <param name="contract">The model's contract.</param>
        /// <param name="track">The character's key poses (at least two keys).</param>
        /// <param name="jointMap">As for <see cref="Retargeting"/>.</param>
        /// <param name="methods">What fills the gaps, in order.</param>
        /// <param name="progress">Gaps filled over every method, or null.</param>
        /// <param name="maxBoneDeviationDegrees">As for <see cref="Retargeting"/> (the component's default).</param>
        /// <exception cref="KeyLayoutException">Too few keys, or a gap the model cannot take.</exception>
        /// <exception cref="JointMapException">The character cannot be mapped onto the model.</exception>
        public static BakeRun Run(ModelContract contract, CharacterPoseTrack track, JointMap? jointMap, IReadOnlyList<BakeMethod> methods, IProgress<StageProgress>? progress = null,
            double maxBoneDeviationDegrees = CharacterRig.DefaultMaxBoneDeviationDegrees)
        {
            if (track == null) throw new ArgumentNullException(nameof(track));
            var keys = new int[track.KeyFrames.Count];
            int k = 0;
            foreach (int frame in track.KeyFrames) keys[k++] = frame;
            if (keys.Length < 2) throw new KeyLayoutException($"{keys.Length} key pose{(keys.Length == 1 ? "" : "s")}", "expected at least two keys with a gap between them");
            MappedRig rig = Retargeting(contract, track.Rig, jointMap, track.Motion.FrameTime, maxBoneDeviationDegrees);
            return InbetweenBake.Run(track.Motion, keys, rig, methods, progress);
        }
    }
}
