using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>The result of <see cref="InbetweenBake.Run"/>: the seam, the keys on both timelines and one <see cref="MethodBake"/> per method, in order.</summary>
    public sealed class BakeRun
    {
        internal BakeRun(IRigRetargeting rig, MotionClip groundTruthOnModel, int[] rigKeys, int[] modelKeys, MethodBake[] methods, string[]? warnings = null)
        {
            Warnings = warnings ?? Array.Empty<string>();
            Rig = rig;
            GroundTruthOnModel = groundTruthOnModel;
            RigKeys = rigKeys;
            ModelKeys = modelKeys;
            Methods = methods;
        }

        /// <summary>How the rig's motion reached the model's skeleton and rate.</summary>
        public IRigRetargeting Rig { get; }

        /// <summary>The rig's clip on the model's skeleton and rate (every frame, not only the keys: the truth there).</summary>
        public MotionClip GroundTruthOnModel { get; }

        /// <summary>The keys as frames of the rig's clip.</summary>
        public IReadOnlyList<int> RigKeys { get; }

        /// <summary>The keys as frames of <see cref="GroundTruthOnModel"/>.</summary>
        public IReadOnlyList<int> ModelKeys { get; }

        /// <summary>One result per method, in the order they were given.</summary>
        public IReadOnlyList<MethodBake> Methods { get; }

        /// <summary>
        /// What the run did not do as asked, one line each (e.g. foot locking skipped on a rig whose legs cannot be
        /// bent); empty when everything was done. Front ends show them as warnings.
        /// </summary>
        public IReadOnlyList<string> Warnings { get; }

        /// <summary>The result of the method called <paramref name="name"/>.</summary>
        /// <exception cref="ArgumentException">No method of that name was baked.</exception>
        public MethodBake this[string name]
        {
            get
            {
                foreach (MethodBake m in Methods)
                {
                    if (string.Equals(m.Method.Name, name, StringComparison.Ordinal)) return m;
                }

                throw new ArgumentException($"no method named '{name}' was baked", nameof(name));
            }
        }
    }
}
