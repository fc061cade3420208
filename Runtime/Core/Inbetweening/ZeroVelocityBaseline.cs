using System;

namespace DeltaInterpolator.Core.Inbetweening
{
    /// <summary>
    /// The official zero-velocity baseline: every missing frame repeats the last past key frame's root
    /// position and local rotations (the pose freezes, then snaps to the target).
    /// </summary>
    public sealed class ZeroVelocityBaseline : IInbetweener
    {
        /// <inheritdoc />
        public string Id => "zerovel";

        /// <inheritdoc />
        public string DisplayName => "Zero-V";

        /// <inheritdoc />
        public void Inbetween(Transition transition)
        {
            int j = transition.Skeleton.JointCount;
            int last = transition.PastFrames - 1;
            ReadOnlySpan<double> root = transition.KeyRootPositions.AsSpan(last * 3, 3);
            ReadOnlySpan<double> pose = transition.KeyLocalRotations.AsSpan(last * j * 4, j * 4);
            for (int f = 0; f < transition.MissingFrames; f++)
            {
                root.CopyTo(transition.RootPositions.AsSpan(f * 3, 3));
                pose.CopyTo(transition.LocalRotations.AsSpan(f * j * 4, j * 4));
            }
        }
    }
}
