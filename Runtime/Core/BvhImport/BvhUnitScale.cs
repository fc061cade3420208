using System;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// How many metres one unit of a BVH file is. The format has no unit field, and libraries differ:
    /// LaFAN1 is in centimetres, B. Hahne's CMU conversion in the CMU database's own unit (1/0.45 inch),
    /// others in metres, millimetres or inches. A person's leg is about 0.9 m in all of them, so the unit
    /// whose leg length lands nearest to that (on a log scale) is the file's.
    /// </summary>
    public static class BvhUnitScale
    {
        /// <summary>A typical standing leg length (root height above the feet), metres.</summary>
        internal const double TypicalLegLength = 0.9;

        /// <summary>The CMU database's unit: ASF files say <c>length 0.45</c>, i.e. one unit is 1/0.45 inch.</summary>
        public const double CmuUnit = 0.0254 / 0.45;

        /// <summary>The units a file may be in, metres per unit, tried in this order (the first wins a tie).</summary>
        public static readonly double[] Candidates = { 0.01, 1.0, 0.001, 0.0254, CmuUnit };

        /// <summary>
        /// The candidate unit that makes the skeleton's leg (<see cref="RestLegLength"/>) closest to
        /// <see cref="TypicalLegLength"/>.
        /// </summary>
        /// <param name="skeleton">The file's skeleton.</param>
        /// <param name="sourceName">The file, for the message.</param>
        /// <exception cref="DataFormatException">The rest pose has no leg (nothing below the root): there is nothing to measure.</exception>
        public static double Detect(Skeleton skeleton, string sourceName)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            double leg = RestLegLength(skeleton);
            if (!(leg > 0))
            {
                throw new DataFormatException(sourceName ?? "<bvh>", "the rest pose has no joint below the root, so the file's unit cannot be told from a leg length",
                    "expected a standing skeleton (legs below the root), or set Metres Per Unit in the importer");
            }

            double best = Candidates[0];
            double bestDistance = double.PositiveInfinity;
            foreach (double unit in Candidates)
            {
                double distance = Math.Abs(Math.Log(leg * unit / TypicalLegLength));
                if (distance < bestDistance)
                {
                    best = unit;
                    bestDistance = distance;
                }
            }

            return best;
        }

        /// <summary>
        /// The root's height above the lowest joint at the skeleton's reference pose, file units: its rest pose
        /// (all rotations zero), or for a skeleton with LaFAN1's joint names the model's T-pose, as LaFAN1's
        /// rest pose has every bone along +X (<see cref="ReferencePose.Default"/>).
        /// </summary>
        public static double RestLegLength(Skeleton skeleton)
        {
            if (skeleton == null) throw new ArgumentNullException(nameof(skeleton));
            ReferencePose rest = ReferencePose.Default(skeleton);
            double lowest = double.PositiveInfinity;
            for (int j = 0; j < skeleton.JointCount; j++) lowest = Math.Min(lowest, rest.GlobalPosition(j).Y);
            return rest.GlobalPosition(0).Y - lowest;
        }
    }
}
