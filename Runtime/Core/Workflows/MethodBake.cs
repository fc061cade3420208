using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// What one <see cref="BakeMethod"/> produced in a bake: its plan, its clip on the model's skeleton and on the rig's, and
    /// its time. Built by <see cref="InbetweenBake"/>.
    /// </summary>
    /// <param name="Method">The method.</param>
    /// <param name="Plan">Its plan (gaps, warnings about gaps outside the trained ranges).</param>
    /// <param name="OnModel">The bake on the model's skeleton and rate: model frames of the first to the last key.</param>
    /// <param name="OnRig">The bake on the rig's skeleton and rate: rig frames of the first to the last key, key frames the rig's own.</param>
    /// <param name="Seconds">Seconds the bake took (filling the gaps, not the retargeting).</param>
    /// <param name="Contacts">
    /// The contacts the method predicted on <see cref="OnModel"/>'s frames (a model with a contact output; none for SLERP
    /// or a model without it): what the bake's foot lockers planted feet by, labelling them where there is none.
    /// </param>
    public sealed record MethodBake(BakeMethod Method, BakePlan Plan, MotionClip OnModel, MotionClip OnRig, double Seconds, FootContacts Contacts);
}
