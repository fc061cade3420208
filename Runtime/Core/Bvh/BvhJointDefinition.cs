using System.Collections.Generic;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>One joint as the HIERARCHY section declares it, in file order (parents before children).</summary>
    internal sealed class BvhJointDefinition
    {
        /// <summary>The name from the ROOT or JOINT line (words joined by single spaces).</summary>
        public string Name = "";

        /// <summary>Index of the parent joint; −1 for the root.</summary>
        public int Parent;

        /// <summary>Line of the ROOT or JOINT keyword.</summary>
        public int Line;

        /// <summary>The OFFSET (valid when <see cref="HasOffset"/>).</summary>
        public Vector3D Offset;

        /// <summary>True once the OFFSET line was read.</summary>
        public bool HasOffset;

        /// <summary>The CHANNELS line; null until read.</summary>
        public BvhChannel[]? Channels;

        /// <summary>The offsets of the joint's End Sites (kept for writing; not joints).</summary>
        public readonly List<Vector3D> EndSites = new List<Vector3D>();
    }
}
