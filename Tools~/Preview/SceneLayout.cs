using System;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// Where a scene's tracks stand and how big things are, derived once from the data so that the HTML
    /// player and the contact sheet agree: character height, floor height, the main direction of travel
    /// and the sideways axis along which tracks stand apart.
    /// </summary>
    internal sealed class SceneLayout
    {
        private SceneLayout(double height, double floor, double[] travel, double[] lateral, double spacing, double quantum)
        {
            Height = height;
            Floor = floor;
            Travel = travel;
            Lateral = lateral;
            Spacing = spacing;
            Quantum = quantum;
        }

        /// <summary>Vertical extent of the reference track's first pose (data units; 1 when degenerate).</summary>
        public double Height { get; }

        /// <summary>Lowest joint height over every track and frame: where the ground grid lies.</summary>
        public double Floor { get; }

        /// <summary>Unit XZ direction (x, 0, z) from the reference track's first body-root position to its last (+Z when it hardly moves).</summary>
        public double[] Travel { get; }

        /// <summary>Unit XZ direction perpendicular to <see cref="Travel"/>: tracks stand apart along it.</summary>
        public double[] Lateral { get; }

        /// <summary>Distance between neighbouring tracks along <see cref="Lateral"/>.</summary>
        public double Spacing { get; }

        /// <summary>
        /// Rounding step of positions written for the player: a power of ten near 1/5000 of the height,
        /// i.e. 0.1 mm for a person in centimetres or metres.
        /// </summary>
        public double Quantum { get; }

        /// <summary>The index of the track the layout follows: the ground truth, else the first.</summary>
        public static int ReferenceTrack(PreviewScene scene) => scene.GroundTruthTrack >= 0 ? scene.GroundTruthTrack : 0;

        public static SceneLayout Of(PreviewScene scene)
        {
            PreviewTrack reference = scene.Tracks[ReferenceTrack(scene)];
            int joints = scene.JointCount;

            double minY = double.PositiveInfinity, maxY = double.NegativeInfinity;
            double minX = double.PositiveInfinity, maxX = double.NegativeInfinity, minZ = double.PositiveInfinity, maxZ = double.NegativeInfinity;
            for (int j = 0; j < joints; j++)
            {
                (double x, double y, double z) = reference.At(0, j);
                minY = Math.Min(minY, y);
                maxY = Math.Max(maxY, y);
                minX = Math.Min(minX, x);
                maxX = Math.Max(maxX, x);
                minZ = Math.Min(minZ, z);
                maxZ = Math.Max(maxZ, z);
            }

            // A lying or crouching first pose is short: the largest extent still gives the body's size.
            double height = Math.Max(maxY - minY, Math.Max(maxX - minX, maxZ - minZ));
            if (!(height > 1e-9)) height = 1;

            double floor = double.PositiveInfinity;
            foreach (PreviewTrack track in scene.Tracks)
            {
                double[] p = track.GlobalPositions;
                for (int i = 1; i < p.Length; i += 3) floor = Math.Min(floor, p[i]);
            }

            // The body root, not the file's root: a root node left at the world origin never travels.
            int body = scene.BodyRoot;
            (double x0, _, double z0) = reference.At(0, body);
            (double x1, _, double z1) = reference.At(reference.FrameCount - 1, body);
            double dx = x1 - x0, dz = z1 - z0;
            double length = Math.Sqrt(dx * dx + dz * dz);
            double[] travel = length > 0.5 * height ? new[] { dx / length, 0, dz / length } : new[] { 0.0, 0, 1 };
            double[] lateral = { travel[2], 0, -travel[0] };

            // Tracks stand apart by the root's sideways wander plus a body width, within sensible bounds.
            double lo = double.PositiveInfinity, hi = double.NegativeInfinity;
            for (int f = 0; f < reference.FrameCount; f++)
            {
                (double x, _, double z) = reference.At(f, body);
                double s = x * lateral[0] + z * lateral[2];
                lo = Math.Min(lo, s);
                hi = Math.Max(hi, s);
            }

            double spacing = Math.Min(Math.Max(hi - lo + 0.6 * height, 0.8 * height), 2.0 * height);
            double quantum = Math.Pow(10, Math.Floor(Math.Log10(height / 5000)));
            return new SceneLayout(height, floor, travel, lateral, spacing, quantum);
        }

        /// <summary>Sideways offset (x, 0, z) of track <paramref name="index"/> of <paramref name="count"/>, the row centred on the data.</summary>
        public double[] OffsetOf(int index, int count)
        {
            double s = (index - (count - 1) / 2.0) * Spacing;
            return new[] { s * Lateral[0], 0, s * Lateral[2] };
        }
    }
}
