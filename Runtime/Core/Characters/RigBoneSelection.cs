using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Core.Characters
{
    /// <summary>
    /// Which of a character's transforms the component drives: the bones that play a part (a
    /// <c>HumanBodyBones</c> bone of a humanoid avatar, or a bone a joint map names) and every transform on
    /// the paths between them and the root bone (an unnamed neck joint, a spine joint the avatar skips),
    /// parents first, the root bone first. Everything else (fingers, twist bones, props, the armature above
    /// the root bone) is left to the character's own animation.
    /// </summary>
    public sealed class RigBoneSelection
    {
        private RigBoneSelection(int[] transforms, string[] names, int[] parents)
        {
            Transforms = transforms;
            BoneNames = names;
            Parents = parents;
        }

        /// <summary>The driven transforms, as indices into the list given to <see cref="Select"/>, parents first.</summary>
        public IReadOnlyList<int> Transforms { get; }

        /// <summary>Each driven bone's name: the part it plays, or its own name for a bone between parts (made unique).</summary>
        public IReadOnlyList<string> BoneNames { get; }

        /// <summary>Each driven bone's parent among the driven bones (−1 for the root bone).</summary>
        public IReadOnlyList<int> Parents { get; }

        /// <summary>
        /// Selects the bones to drive.
        /// </summary>
        /// <param name="transformNames">Every transform under the character, depth first (a parent before its children).</param>
        /// <param name="transformParents">Each transform's parent index in the same list (−1 for one directly under the character).</param>
        /// <param name="roles">Per transform, the part it plays (its bone name in the joint map), or null.</param>
        /// <param name="root">The root bone's transform index (the hips), −1 when the rig has none.</param>
        /// <param name="rootName">The root's part for messages (e.g. <c>Hips</c>).</param>
        /// <param name="character">The character's name for messages.</param>
        /// <exception cref="JointMapException">No transform plays the root, or parts lie outside the root bone's hierarchy (all named).</exception>
        public static RigBoneSelection Select(IReadOnlyList<string> transformNames, IReadOnlyList<int> transformParents, IReadOnlyList<string?> roles, int root, string rootName, string character)
        {
            if (transformNames == null) throw new ArgumentNullException(nameof(transformNames));
            if (transformParents == null) throw new ArgumentNullException(nameof(transformParents));
            if (roles == null) throw new ArgumentNullException(nameof(roles));
            int n = transformNames.Count;
            if (transformParents.Count != n || roles.Count != n) throw new ArgumentException($"{n} transforms need {n} parents and {n} roles");
            for (int t = 0; t < n; t++)
            {
                if (transformParents[t] >= t) throw new ArgumentException($"transform {t} ('{transformNames[t]}') has parent {transformParents[t]}; expected a depth-first list, parents before children", nameof(transformParents));
            }

            if (root < 0 || root >= n)
            {
                throw new JointMapException(character, $"no bone plays the root '{rootName}'", "expected the hips bone: set the avatar's Hips, or name the root bone in the joint map", new[] { rootName });
            }

            var keep = new bool[n];
            keep[root] = true;
            var outside = new List<string>();
            for (int t = 0; t < n; t++)
            {
                if (roles[t] == null || t == root) continue;
                int walk = t;
                while (walk >= 0 && walk != root) walk = transformParents[walk];
                if (walk != root)
                {
                    outside.Add($"{roles[t]} ('{transformNames[t]}')");
                    continue;
                }

                for (int k = t; k != root && !keep[k]; k = transformParents[k]) keep[k] = true;
            }

            if (outside.Count > 0)
            {
                throw new JointMapException(character, $"bone(s) {string.Join(", ", outside)} are not below the root bone '{transformNames[root]}'",
                    "expected every mapped bone in the hierarchy under the hips; fix the avatar's bone assignment or the joint map");
            }

            var transforms = new List<int>();
            var index = new int[n];
            for (int t = 0; t < n; t++)
            {
                index[t] = -1;
                if (!keep[t]) continue;
                index[t] = transforms.Count;
                transforms.Add(t);
            }

            var used = new HashSet<string>(StringComparer.Ordinal);
            foreach (int t in transforms) if (roles[t] != null) used.Add(roles[t]!);
            // The root bone plays its part even when the caller found it otherwise (e.g. by the avatar's Hips).
            var names = new string[transforms.Count];
            var parents = new int[transforms.Count];
            for (int b = 0; b < names.Length; b++)
            {
                int t = transforms[b];
                parents[b] = t == root ? -1 : index[transformParents[t]];
                string? role = t == root ? roles[t] ?? rootName : roles[t];
                string name = role ?? transformNames[t];
                // A bone between parts may share a name with a part or another such bone; the skeleton needs unique names.
                if (role == null)
                {
                    string unique = name;
                    for (int k = 2; used.Contains(unique) || string.IsNullOrWhiteSpace(unique); k++) unique = (string.IsNullOrWhiteSpace(name) ? "bone" : name) + "#" + k;
                    name = unique;
                    used.Add(name);
                }

                names[b] = name;
            }

            return new RigBoneSelection(transforms.ToArray(), names, parents);
        }

        /// <summary>
        /// The part each transform plays under <paramref name="map"/> (every name in its chains), found as
        /// <see cref="JointMap.FindJoint"/> finds joints: by exact name, else ignoring namespace prefixes.
        /// </summary>
        /// <exception cref="JointMapException">A name the map needs matches several transforms (named).</exception>
        /// <param name="transformNames">Every transform under the character, depth first.</param>
        /// <param name="map">Model joint → bone chains.</param>
        /// <param name="rootJoint">The model's root joint (its chain's first bone is the root bone).</param>
        /// <param name="character">The character's name for messages.</param>
        /// <param name="rootTransform">The root bone's transform index, or −1 when no transform has its name.</param>
        public static string?[] RolesFromJointMap(IReadOnlyList<string> transformNames, JointMap map, string rootJoint, string character, out int rootTransform)
        {
            if (transformNames == null) throw new ArgumentNullException(nameof(transformNames));
            if (map == null) throw new ArgumentNullException(nameof(map));
            var roles = new string?[transformNames.Count];
            var ambiguous = new List<string>();
            rootTransform = -1;
            foreach (string target in map.TargetJoints)
            {
                IReadOnlyList<string>? chain = map.SourceChain(target);
                if (chain == null) continue;
                for (int i = 0; i < chain.Count; i++)
                {
                    int found = Find(transformNames, chain[i], ambiguous);
                    if (found < 0) continue;
                    roles[found] = transformNames[found];
                    if (i == 0 && string.Equals(target, rootJoint, StringComparison.Ordinal)) rootTransform = found;
                }
            }

            if (ambiguous.Count > 0)
            {
                throw new JointMapException(character, $"several transforms are called {string.Join(", ", ambiguous)}",
                    "expected each bone the joint map names once under the Animator; rename the duplicates or name the bones in a JSON joint map");
            }

            return roles;
        }

        private static int Find(IReadOnlyList<string> names, string wanted, List<string> ambiguous)
        {
            int exact = -1, bare = -1, bareCount = 0, exactCount = 0;
            string wantedBare = StripNamespace(wanted);
            for (int t = 0; t < names.Count; t++)
            {
                if (string.Equals(names[t], wanted, StringComparison.Ordinal))
                {
                    exact = t;
                    exactCount++;
                }
                else if (string.Equals(StripNamespace(names[t]), wantedBare, StringComparison.Ordinal))
                {
                    bare = t;
                    bareCount++;
                }
            }

            if (exactCount == 1) return exact;
            if (exactCount > 1 || (exactCount == 0 && bareCount > 1))
            {
                ambiguous.Add($"'{wanted}'");
                return -1;
            }

            return bareCount == 1 ? bare : -1;
        }

        private static string StripNamespace(string name)
        {
            int colon = name.LastIndexOf(':');
            return colon >= 0 ? name.Substring(colon + 1) : name;
        }
    }
}
