using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Feet;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Core.Workflows;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>
    /// The scoring use case of a bake (the CLI's <c>bake</c>, <c>demo</c> and <c>score</c>): every method's
    /// result against the rig's own frames over the non-key frames — accuracy (<see cref="BakeAccuracy"/>) and
    /// foot skating (<see cref="FootSkating"/>, with the ground truth's own as the floor) — and the rig's leg
    /// length that makes scores of different rigs compare.
    /// </summary>
    public sealed class BakeScores
    {
        private BakeScores(MethodScore[] methods, FootSkating truthSkating, double legLength)
        {
            Methods = methods;
            TruthSkating = truthSkating;
            LegLength = legLength;
        }

        /// <summary>One score per method, in the bake's order.</summary>
        public IReadOnlyList<MethodScore> Methods { get; }

        /// <summary>The ground truth's own foot skating over the same frames.</summary>
        public FootSkating TruthSkating { get; }

        /// <summary>The rig's leg length in its units (<see cref="IRigRetargeting.LegLength"/>).</summary>
        public double LegLength { get; }

        /// <summary>The scores of the method called <paramref name="name"/>.</summary>
        /// <exception cref="ArgumentException">No method of that name was scored.</exception>
        public MethodScore this[string name]
        {
            get
            {
                foreach (MethodScore m in Methods)
                {
                    if (string.Equals(m.Name, name, StringComparison.Ordinal)) return m;
                }

                throw new ArgumentException($"no method named '{name}' was scored", nameof(name));
            }
        }

        /// <summary>The feet of the rig <paramref name="run"/> baked on (<paramref name="rigSkeleton"/>): its map's source legs, or the model's.</summary>
        public static FootRig Feet(BakeRun run, Skeleton rigSkeleton)
        {
            if (run == null) throw new ArgumentNullException(nameof(run));
            return run.Rig.Map != null ? FootRig.ForSource(run.Rig.Map) : FootRig.ForModel(rigSkeleton);
        }

        /// <summary>Scores every method of <paramref name="run"/> against <paramref name="truth"/>, the rig's clip it baked from.</summary>
        /// <param name="truth">The rig's clip (the keys' source).</param>
        /// <param name="run">The bake.</param>
        /// <param name="standardDeviations">Per-coordinate std for L2P on the rig's skeleton, or null (no L2P).</param>
        public static BakeScores Measure(MotionClip truth, BakeRun run, double[]? standardDeviations = null)
        {
            if (truth == null) throw new ArgumentNullException(nameof(truth));
            if (run == null) throw new ArgumentNullException(nameof(run));
            FootRig feet = Feet(run, truth.Skeleton);
            var methods = new MethodScore[run.Methods.Count];
            for (int i = 0; i < methods.Length; i++)
            {
                MethodBake m = run.Methods[i];
                methods[i] = new MethodScore(m.Method.Name,
                    BakeAccuracy.Measure(truth, m.OnRig, run.RigKeys, standardDeviations),
                    FootSkating.Measure(truth, m.OnRig, run.RigKeys, feet));
            }

            return new BakeScores(methods, FootSkating.OfTruth(truth, run.RigKeys, feet), run.Rig.LegLength);
        }
    }
}
