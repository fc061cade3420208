using System;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>One animated degree of freedom of a BVH joint, as named on its CHANNELS line.</summary>
    public enum BvhChannel
    {
        /// <summary>Translation along X (data units).</summary>
        Xposition,
        /// <summary>Translation along Y (data units).</summary>
        Yposition,
        /// <summary>Translation along Z (data units).</summary>
        Zposition,
        /// <summary>Rotation about X (degrees).</summary>
        Xrotation,
        /// <summary>Rotation about Y (degrees).</summary>
        Yrotation,
        /// <summary>Rotation about Z (degrees).</summary>
        Zrotation,
    }

    /// <summary>Look-ups for <see cref="BvhChannel"/>.</summary>
    public static class BvhChannels
    {
        /// <summary>True for the three rotation channels.</summary>
        public static bool IsRotation(this BvhChannel channel) => channel >= BvhChannel.Xrotation;

        /// <summary>The channel's axis: 0 = X, 1 = Y, 2 = Z.</summary>
        public static int Axis(this BvhChannel channel) => (int)channel % 3;

        /// <summary>Parses a channel name exactly as BVH spells it (case-sensitive).</summary>
        public static bool TryParse(string name, out BvhChannel channel)
        {
            switch (name)
            {
                case "Xposition": channel = BvhChannel.Xposition; return true;
                case "Yposition": channel = BvhChannel.Yposition; return true;
                case "Zposition": channel = BvhChannel.Zposition; return true;
                case "Xrotation": channel = BvhChannel.Xrotation; return true;
                case "Yrotation": channel = BvhChannel.Yrotation; return true;
                case "Zrotation": channel = BvhChannel.Zrotation; return true;
                default: channel = default; return false;
            }
        }

        /// <summary>The channels of a joint as they would appear on its CHANNELS line.</summary>
        public static string Describe(BvhChannel[] channels) => channels.Length + " " + string.Join(" ", Array.ConvertAll(channels, c => c.ToString()));
    }
}
