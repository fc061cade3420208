using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// The fill of a transform clip in one call, the route the editor's fill takes: the key poses read off the clip's
    /// curves (<see cref="KeyFill.KeyPoses"/>) → the one Core bake (<see cref="CharacterBake.Run"/>, the component's
    /// map) → the first method's frames as keys on the clip's curves (<see cref="KeyFill.Edit(KeyFillPlan, IReadOnlyList{KeyedCurve}, CharacterRig, IReadOnlyList{string}, Skeletons.MotionClip)"/>).
    /// Humanoid clips take the same plan and bake, their key poses sampled and their frames recorded by the engine.
    /// </summary>
    public static class KeyFillBake
    {
        /// <summary>Fills <paramref name="plan"/>'s gaps of <paramref name="curves"/> with <paramref name="method"/>.</summary>
        /// <param name="contract">The model's contract.</param>
        /// <param name="plan">From <see cref="KeyFill.Plan"/> on <paramref name="curves"/>.</param>
        /// <param name="curves">The clip's curves.</param>
        /// <param name="rig">The character.</param>
        /// <param name="jointMap">Model joint → bone chains, or null for the built-in map.</param>
        /// <param name="bonePaths">Each rig bone's path under the animated GameObject.</param>
        /// <param name="scenePose">The bones' current local transforms (what curves the clip lacks leave them at).</param>
        /// <param name="method">What fills the gaps (<see cref="BakeMethod.Model"/>).</param>
        /// <param name="maxBoneDeviationDegrees">As for <see cref="CharacterBake.Run"/>.</param>
        /// <returns>The edit and the bake it came from (its plan's warnings, e.g. gaps outside the trained range).</returns>
        public static (KeyFillEdit Edit, BakeRun Bake) Run(ModelContract contract, KeyFillPlan plan, IReadOnlyList<KeyedCurve> curves, CharacterRig rig, JointMap? jointMap,
            IReadOnlyList<string> bonePaths, ReadOnlySpan<double> scenePose, BakeMethod method, double maxBoneDeviationDegrees = CharacterRig.DefaultMaxBoneDeviationDegrees)
        {
            if (contract == null) throw new ArgumentNullException(nameof(contract));
            if (method == null) throw new ArgumentNullException(nameof(method));
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            if (Math.Abs(plan.FrameRate - contract.FramesPerSecond) > 1e-9 * contract.FramesPerSecond)
            {
                throw new ArgumentException($"the plan counts frames at {plan.FrameRate} fps; the model runs at {contract.FramesPerSecond}: plan at the model's rate", nameof(plan));
            }

            CharacterPoseTrack track = KeyFill.KeyPoses(plan, curves, rig, bonePaths, scenePose);
            BakeRun run = CharacterBake.Run(contract, track, jointMap, new[] { method }, null, maxBoneDeviationDegrees);
            return (KeyFill.Edit(plan, curves, rig, bonePaths, run.Methods[0].OnRig), run);
        }
    }
}
