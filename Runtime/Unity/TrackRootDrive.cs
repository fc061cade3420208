using DeltaInterpolator.Core.Blends;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// What a neural track's job puts on the stream as root motion this frame, decided on the main thread
    /// (<see cref="NeuralBlendLayer.Evaluate"/>) and read by <see cref="TrackBlendJob.ProcessRootMotion"/>: the clips' own
    /// mix, a blend's or gap's travel velocity (scene offsets), or the step onto the track's placement (transform offsets).
    /// </summary>
    internal struct TrackRootDrive
    {
        /// <summary>Which root motion the stream carries.</summary>
        public enum Source : byte
        {
            /// <summary>The clips' mix as it is (or nothing in a gap without travel).</summary>
            Clips,

            /// <summary>A blend's or gap's travel: <see cref="VelocityX"/>, <see cref="VelocityZ"/>, <see cref="YawRate"/>.</summary>
            SpanTravel,

            /// <summary>The track places the character: the step from <see cref="Current"/> to <see cref="Target"/> over the stream's delta time.</summary>
            Placement,
        }

        /// <summary>Which root motion the stream carries.</summary>
        public Source Kind;

        /// <summary>The span's root velocity along x, per second, in the character's frame.</summary>
        public double VelocityX;

        /// <summary>The span's root velocity along z, per second, in the character's frame.</summary>
        public double VelocityZ;

        /// <summary>The span's turn rate about +Y, radians per second.</summary>
        public double YawRate;

        /// <summary>Where the character stands (x, z, yaw in its parent's space, the track's).</summary>
        public RootPlacement Current;

        /// <summary>Where the track has the character now.</summary>
        public RootPlacement Target;
    }
}
