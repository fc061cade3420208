using System.CommandLine;
using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// <c>--accept-reference-pose</c>: the explicit override of the humanoid rule (spine, neck and legs of the reference
    /// pose within 25° of the model's standing pose), the same on every verb that retargets BVH. A flag, not a
    /// setting: what it let through is reported in every output of the run, never silently.
    /// </summary>
    internal static class ReferencePoseArgument
    {
        /// <summary>The option's help, shared so that every verb says the same.</summary>
        public const string Help = "Keep a reference pose whose spine, neck or leg bones point more than 25° from the model's standing pose (refused by default: it bends every retargeted frame the same wrong way). The bones and angles accepted are reported on the console and in every output of the run. Prefer --reference-frame naming a standing frame, or a joint map fix.";

        /// <summary>A new <c>--accept-reference-pose</c> flag.</summary>
        public static Option<bool> Create() => new Option<bool>(BoneDirections.AcceptOption) { Description = Help };
    }
}
