using System;

namespace DeltaInterpolator.Tests.Blends
{
    /// <summary>
    /// One frame of a played track as the engine left it: the director's time and, per figure, where its object stands on
    /// the ground, which way it faces and where its hips are in the world. What <c>NeuralTrackRootMotionVerification</c>
    /// records in Unity and <see cref="TrackMotionChecks"/> judges; plain numbers, so the checks run without the engine too.
    /// </summary>
    public sealed class TrackMotionFrame
    {
        public TrackMotionFrame(double time, FigurePlace[] figures)
        {
            Time = time;
            Figures = figures ?? throw new ArgumentNullException(nameof(figures));
        }

        /// <summary>The director's time, seconds.</summary>
        public double Time { get; }

        /// <summary>Each figure, in the order the recording gives them (<see cref="TrackMotionChecks.Character"/> first).</summary>
        public FigurePlace[] Figures { get; }
    }

    /// <summary>A figure's object on the ground (x, z, its facing about +Y from +Z toward +X, radians) and its hips in the world.</summary>
    public readonly struct FigurePlace
    {
        public FigurePlace(double x, double z, double yaw, double hipsX, double hipsY, double hipsZ)
        {
            X = x;
            Z = z;
            Yaw = yaw;
            HipsX = hipsX;
            HipsY = hipsY;
            HipsZ = hipsZ;
        }

        public double X { get; }

        public double Z { get; }

        public double Yaw { get; }

        public double HipsX { get; }

        public double HipsY { get; }

        public double HipsZ { get; }
    }
}
