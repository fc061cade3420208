using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// What a BVH file holds: the motion (skeleton, frame time, local positions and rotations) plus what
    /// is needed to write the file back in its own layout — each joint's channel list in file order
    /// and the End Site offsets (End Sites are not joints).
    /// </summary>
    public sealed class BvhAnimation
    {
        /// <summary>
        /// <paramref name="motion"/> as a BVH of its own skeleton with LaFAN1's channel layout (root: position
        /// and ZYX rotation, other joints: ZYX rotation; an end site on every leaf): how motion on a model's
        /// skeleton is written (retargeted clips, the demo's ground truth and bakes).
        /// </summary>
        public static BvhAnimation ForSkeleton(MotionClip motion, string name)
        {
            Skeleton skeleton = motion.Skeleton;
            var channels = new BvhChannel[skeleton.JointCount][];
            var endSites = new Vector3D[skeleton.JointCount][];
            var hasChild = new bool[skeleton.JointCount];
            for (int j = 1; j < skeleton.JointCount; j++) hasChild[skeleton.Parents[j]] = true;
            for (int j = 0; j < skeleton.JointCount; j++)
            {
                channels[j] = j == 0
                    ? new[] { BvhChannel.Xposition, BvhChannel.Yposition, BvhChannel.Zposition, BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation }
                    : new[] { BvhChannel.Zrotation, BvhChannel.Yrotation, BvhChannel.Xrotation };
                endSites[j] = hasChild[j] ? Array.Empty<Vector3D>() : new[] { Vector3D.Zero };
            }

            return new BvhAnimation(motion, channels, endSites, name);
        }

        /// <summary>Creates an animation; <paramref name="jointChannels"/> has one entry per joint.</summary>
        /// <param name="motion">The motion.</param>
        /// <param name="jointChannels">Per joint, its channels in CHANNELS-line order: 3 rotations, 3 positions, or all 6.</param>
        /// <param name="endSites">Per joint, the offsets of its End Sites (usually none or one), or null for none anywhere.</param>
        /// <param name="sourceName">File path or other name used in messages.</param>
        public BvhAnimation(MotionClip motion, IReadOnlyList<BvhChannel[]> jointChannels, IReadOnlyList<Vector3D[]>? endSites, string sourceName)
        {
            Motion = motion ?? throw new ArgumentNullException(nameof(motion));
            if (jointChannels == null || jointChannels.Count != motion.Skeleton.JointCount)
            {
                throw new ArgumentException("one channel list per joint is required", nameof(jointChannels));
            }

            var channels = new BvhChannel[jointChannels.Count][];
            int total = 0;
            for (int j = 0; j < channels.Length; j++)
            {
                channels[j] = (BvhChannel[])jointChannels[j].Clone();
                ValidateChannels(channels[j], motion.Skeleton.Names[j]);
                total += channels[j].Length;
            }

            var sites = new Vector3D[channels.Length][];
            for (int j = 0; j < sites.Length; j++)
            {
                sites[j] = endSites != null && endSites[j] != null ? (Vector3D[])endSites[j].Clone() : Array.Empty<Vector3D>();
            }

            if (endSites != null && endSites.Count != channels.Length)
            {
                throw new ArgumentException("one End Site list per joint is required", nameof(endSites));
            }

            JointChannels = channels;
            EndSites = sites;
            ChannelCount = total;
            SourceName = sourceName ?? "<bvh>";
        }

        /// <summary>The motion: skeleton, frames, local positions and rotations.</summary>
        public MotionClip Motion { get; }

        /// <summary>The joint hierarchy (same as <c>Motion.Skeleton</c>).</summary>
        public Skeleton Skeleton => Motion.Skeleton;

        /// <summary>Per joint, its channels in CHANNELS-line order.</summary>
        public IReadOnlyList<BvhChannel[]> JointChannels { get; }

        /// <summary>Per joint, its End Site offsets (empty for most joints).</summary>
        public IReadOnlyList<Vector3D[]> EndSites { get; }

        /// <summary>Total number of channels: the number of values on each motion line.</summary>
        public int ChannelCount { get; }

        /// <summary>File path or name used in messages.</summary>
        public string SourceName { get; }

        /// <summary>
        /// The Euler order of a joint's rotation channels, or null when it has none (position-only joint).
        /// </summary>
        public EulerOrder? RotationOrder(int joint)
        {
            BvhChannel[] channels = JointChannels[joint];
            Span<int> axes = stackalloc int[3];
            int n = 0;
            foreach (BvhChannel c in channels)
            {
                if (c.IsRotation()) axes[n++] = c.Axis();
            }

            return n == 3 ? EulerOrders.FromAxes(axes[0], axes[1], axes[2]) : (EulerOrder?)null;
        }

        internal static string? DescribeChannelProblem(BvhChannel[] channels)
        {
            if (channels.Length != 3 && channels.Length != 6)
            {
                return "a joint has " + channels.Length + " channels";
            }

            int seen = 0, rotations = 0;
            foreach (BvhChannel c in channels)
            {
                int bit = 1 << (int)c;
                if ((seen & bit) != 0) return "channel " + c + " is listed twice";
                seen |= bit;
                if (c.IsRotation()) rotations++;
            }

            if (rotations != 0 && rotations != 3) return "a joint has " + rotations + " rotation channels";
            return null;
        }

        private static void ValidateChannels(BvhChannel[] channels, string joint)
        {
            string? problem = DescribeChannelProblem(channels);
            if (problem != null)
            {
                throw new ArgumentException($"joint '{joint}': {problem}; expected 3 rotation channels, 3 position channels, or all 6, each once");
            }
        }
    }
}
