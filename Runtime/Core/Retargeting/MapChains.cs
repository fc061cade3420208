using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Which source joints each target joint of a <see cref="SkeletonMap"/> follows: the joint map's chains
    /// found in the source skeleton and checked against its hierarchy, the joints the source lacks (made up
    /// as rigid children), and the unmapped source joints carried between mapped ones. Kept apart from the
    /// map so that the map's file holds only the rotations it computes.
    /// </summary>
    internal sealed class MapChains
    {
        private MapChains(int[] sourceOf, int[] sourceFirst, int[][] carried, bool[] synthesized)
        {
            SourceOf = sourceOf;
            SourceFirst = sourceFirst;
            Carried = carried;
            Synthesized = synthesized;
        }

        /// <summary>Target joint → the last joint of its source chain (whose rotation it follows).</summary>
        public int[] SourceOf { get; }

        /// <summary>Target joint → the first joint of its source chain (where its bone starts).</summary>
        public int[] SourceFirst { get; }

        /// <summary>Target joint → source joints above s(j) on its path to s(parent), top first.</summary>
        public int[][] Carried { get; }

        /// <summary>Target joint → true when the source lacks it (a rigid child of its parent).</summary>
        public bool[] Synthesized { get; }

        /// <summary>Finds every target joint's chain in the source skeleton.</summary>
        /// <exception cref="JointMapException">Target joints are missing (all named), or a chain does not fit the source's hierarchy.</exception>
        public static MapChains Resolve(Skeleton ss, Skeleton ts, JointMap map, string sourceName)
        {
        int jt = ts.JointCount;
        var chains = new int[jt][];
        var synthesized = new bool[jt];
        var missing = new List<string>();
        var missingNames = new List<string>();
        for (int j = 0; j < jt; j++)
        {
            IReadOnlyList<string>? chain = map.SourceChain(ts.Names[j]);
            int[]? found = chain == null ? null : JointMap.FindChain(ss, chain);
            if (found == null)
            {
                // A joint the rig lacks: a rigid child of its parent (never the root, never below a missing joint).
                if (j > 0 && map.MayLack(ts.Names[j]) && (chains[ts.Parents[j]] != null || synthesized[ts.Parents[j]]))
                {
                    synthesized[j] = true;
                    continue;
                }

                missing.Add(chain == null ? ts.Names[j] : ts.Names[j] + " (" + string.Join("+", chain) + ")");
                missingNames.Add(ts.Names[j]);
                continue;
            }

            chains[j] = found;
        }

        if (missing.Count > 0)
        {
            var names = missingNames;
            throw new JointMapException(sourceName,
                $"the skeleton has no joint for {missing.Count} of the target's {jt} joints: {string.Join(", ", missing)} (joint map '{map.Name}')",
                "expected joints named as in LaFAN1, CMU, Mixamo or Unity HumanBodyBones; pass a JSON joint map (--map) naming the source joint of each",
                names);
        }

        var owner = new int[ss.JointCount];
        for (int s = 0; s < owner.Length; s++) owner[s] = -1;
        var sourceOf = new int[jt];
        var sourceFirst = new int[jt];
        var carried = new int[jt][];
        for (int j = 0; j < jt; j++)
        {
            if (synthesized[j])
            {
                // Turns rigidly with its parent: the same source joint, so its local rotation is the reference's.
                sourceOf[j] = sourceOf[ts.Parents[j]];
                sourceFirst[j] = sourceOf[j];
                carried[j] = Array.Empty<int>();
                continue;
            }

            int[] chain = chains[j];
            for (int i = 0; i < chain.Length; i++)
            {
                int s = chain[i];
                if (owner[s] >= 0)
                {
                    throw new JointMapException(sourceName, $"source joint '{ss.Names[s]}' is mapped to both '{ts.Names[owner[s]]}' and '{ts.Names[j]}'",
                        "expected each source joint in at most one target joint's chain; fix the joint map");
                }

                owner[s] = j;
                if (i > 0 && ss.Parents[s] != chain[i - 1])
                {
                    throw new JointMapException(sourceName, $"the chain of '{ts.Names[j]}' lists '{ss.Names[s]}' after '{ss.Names[chain[i - 1]]}', which is not its parent",
                        "expected a chain of source joints, each the child of the one before");
                }
            }

            sourceOf[j] = chain[chain.Length - 1];
            sourceFirst[j] = chain[0];
            int stop = j == 0 ? -1 : sourceOf[ts.Parents[j]];
            var path = new List<int>();
            int walk = ss.Parents[sourceOf[j]];
            while (walk != stop)
            {
                if (walk < 0)
                {
                    throw new JointMapException(sourceName,
                        $"'{ts.Names[j]}' maps to '{ss.Names[sourceOf[j]]}', which is not below '{ss.Names[stop]}' (the source joint of its parent '{ts.Names[ts.Parents[j]]}')",
                        "expected the source joints to keep the target's hierarchy; fix the joint map");
                }

                path.Add(walk);
                walk = ss.Parents[walk];
            }

            path.Reverse();
            carried[j] = path.ToArray();
        }

            return new MapChains(sourceOf, sourceFirst, carried, synthesized);
        }
    }
}
