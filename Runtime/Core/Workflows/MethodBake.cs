using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>What one <see cref="BakeMethod"/> produced in a bake: its plan, its clip on the model's skeleton and on the rig's, and its time.</summary>
    public sealed class MethodBake
    {
        internal MethodBake(BakeMethod method, BakePlan plan, MotionClip onModel, MotionClip onRig, double seconds)
        {
            Method = method;
            Plan = plan;
            OnModel = onModel;
            OnRig = onRig;
            Seconds = seconds;
        }

        /// <summary>The method.</summary>
        public BakeMethod Method { get; }

        /// <summary>Its plan (gaps, warnings about gaps outside the trained ranges).</summary>
        public BakePlan Plan { get; }

        /// <summary>The bake on the model's skeleton and rate: model frames of the first to the last key.</summary>
        public MotionClip OnModel { get; }

        /// <summary>The bake on the rig's skeleton and rate: rig frames of the first to the last key, key frames the rig's own.</summary>
        public MotionClip OnRig { get; }

        /// <summary>Seconds the bake took (filling the gaps, not the retargeting).</summary>
        public double Seconds { get; }
    }
}
