using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>What one <see cref="BakeMethod"/> produced in a bake: its plan, its clip on the model's skeleton and on the rig's, and its time.</summary>
    public sealed class MethodBake
    {
        internal MethodBake(BakeMethod method, BakePlan plan, MotionClip onModel, MotionClip onRig, double seconds, FootContacts contacts)
        {
            Contacts = contacts;
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

        /// <summary>
        /// The contacts the method predicted on <see cref="OnModel"/>'s frames (a model with a contact output; none for SLERP
        /// or a model without it): what the bake's foot lockers planted feet by, labelling them where there is none.
        /// </summary>
        public FootContacts Contacts { get; }

        /// <summary>Seconds the bake took (filling the gaps, not the retargeting).</summary>
        public double Seconds { get; }
    }
}
