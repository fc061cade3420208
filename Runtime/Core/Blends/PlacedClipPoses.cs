using System;
using DeltaInterpolator.Core.Characters;

namespace DeltaInterpolator.Core.Blends
{
    /// <summary>
    /// A clip's poses moved on the ground by one <see cref="RootPlacement"/> (<see cref="RootPlacement.Move"/>): how a blend's
    /// or gap's target key is put where the character stands when the span ends, in the frame of the first clip's keys.
    /// Allocation-free per sample.
    /// </summary>
    public sealed class PlacedClipPoses : IClipPoses
    {
        private readonly IClipPoses _clip;
        private readonly CharacterRig _rig;
        private readonly RootPlacement _placement;

        /// <summary>The poses of <paramref name="clip"/> on <paramref name="rig"/>, moved by <paramref name="placement"/>.</summary>
        public PlacedClipPoses(IClipPoses clip, CharacterRig rig, RootPlacement placement)
        {
            _clip = clip ?? throw new ArgumentNullException(nameof(clip));
            _rig = rig ?? throw new ArgumentNullException(nameof(rig));
            RootPlacement.RequireFinite(placement, nameof(placement));

            _placement = placement;
        }

        /// <inheritdoc />
        public string Name => _clip.Name;

        /// <inheritdoc />
        public void Sample(double time, Span<double> rootPosition, Span<double> localRotations)
        {
            _clip.Sample(time, rootPosition, localRotations);
            _placement.Move(_rig, rootPosition, localRotations.Slice(0, 4));
        }
    }
}
