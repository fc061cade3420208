using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// Checks on motion before a verb writes or draws it. The check itself is Core's
    /// <see cref="FinitePositions"/>, so that the preview assembly (and any front end) applies the same one.
    /// </summary>
    internal static class MotionChecks
    {
        /// <inheritdoc cref="FinitePositions.Require"/>
        public static void RequireFinitePositions(MotionClip clip, string source, string what) => FinitePositions.Require(clip, source, what);
    }
}
