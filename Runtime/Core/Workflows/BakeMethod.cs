using System;
using DeltaInterpolator.Core.Baking;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>
    /// One way of filling gaps in a bake: an <see cref="IInbetweener"/> (not owned) and the settings it is
    /// baked with. A bake runs any list of them (<see cref="InbetweenBake.Run"/>); <see cref="Model"/> and
    /// <see cref="Slerp"/> are the two every front end offers.
    /// </summary>
    public sealed class BakeMethod
    {
        /// <summary>A method called <paramref name="name"/>.</summary>
        public BakeMethod(string name, IInbetweener inbetweener, BakeSettings settings)
        {
            Name = name ?? throw new ArgumentNullException(nameof(name));
            Inbetweener = inbetweener ?? throw new ArgumentNullException(nameof(inbetweener));
            Settings = settings ?? throw new ArgumentNullException(nameof(settings));
        }

        /// <summary>Its name in reports, e.g. "Model" or "SLERP".</summary>
        public string Name { get; }

        /// <summary>What fills the gaps.</summary>
        public IInbetweener Inbetweener { get; }

        /// <summary>Past context, short-context policy, trained ranges, foot locking.</summary>
        public BakeSettings Settings { get; }

        /// <summary>
        /// The network: its trained past range decides the short-context policy unless one is given; past
        /// context from filled frames too (<paramref name="filledContext"/>) or key frames only.
        /// </summary>
        /// <param name="model">The loaded model (not owned).</param>
        /// <param name="shortContext">Where fewer past frames exist than it wants; null: from its trained range.</param>
        /// <param name="filledContext">Whether frames already filled are past context (the model was trained on consecutive frames).</param>
        /// <param name="feet">Foot locking of the filled frames, or null for none.</param>
        public static BakeMethod Model(Inbetweener model, ShortContextPolicy? shortContext = null, bool filledContext = true, FootLockSettings? feet = null)
        {
            BakeSettings settings = BakeSettings.ForModel(model.Contract, shortContext);
            settings.FilledFramesAsContext = filledContext;
            settings.FootLocking = feet;
            return new BakeMethod("Model", model, settings);
        }

        /// <summary>
        /// SLERP of the key poses. With foot locking, <see cref="FootLockSettings.ForInterpolation"/>: SLERP's feet
        /// slide steadily whatever the truth did, so its timing says nothing about when a foot lifts.
        /// </summary>
        public static BakeMethod Slerp(bool lockFeet = false) =>
            new BakeMethod("SLERP", new SlerpBaseline(), new BakeSettings { Name = "SLERP", FootLocking = lockFeet ? FootLockSettings.ForInterpolation() : null });
    }
}
