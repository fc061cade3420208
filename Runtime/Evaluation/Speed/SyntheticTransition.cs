using System;
using DeltaInterpolator.Core.Inbetweening;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Evaluation.Speed
{
    /// <summary>
    /// A plausible request on a model's skeleton for timing: the root walking along +X at hip height, small
    /// random joint rotations (timings do not depend on the values, so no motion capture is needed).
    /// </summary>
    public static class SyntheticTransition
    {
        /// <summary>A request with <paramref name="pastFrames"/> past keys, <paramref name="missingFrames"/> missing frames and one target key.</summary>
        public static Transition Create(ModelContract contract, int pastFrames, int missingFrames)
        {
            var t = new Transition(contract.Skeleton, pastFrames, missingFrames);
            var random = new Random(missingFrames);
            int j = contract.JointCount;
            for (int k = 0; k < t.KeyFrameCount; k++)
            {
                int frame = k < pastFrames ? k : pastFrames + missingFrames;
                new Vector3D(2.0 * frame / contract.UnitScale * 0.01, 0.9 / contract.UnitScale, 0).Write(t.KeyRootPositions, 3 * k);
                for (int joint = 0; joint < j; joint++)
                {
                    var axis = new Vector3D(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
                    QuaternionD q = Quaternions.FromAxisAngle((1.0 / Math.Max(axis.Length, 1e-9)) * axis, 0.4 * random.NextDouble());
                    q.Write(t.KeyLocalRotations, (k * j + joint) * 4);
                }
            }

            return t;
        }
    }
}
