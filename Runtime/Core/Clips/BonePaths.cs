using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// Finds each model joint's bone under a character by name: the transform paths (relative to the
    /// character, '/'-separated, as Unity's curve bindings write them) whose last name equals the joint's.
    /// When several match, the shallowest wins (a rig's own bones sit above props named like them).
    /// </summary>
    public static class BonePaths
    {
        /// <summary>
        /// Resolves every joint name to a transform path, or null when the character has no such bone.
        /// </summary>
        /// <param name="jointNames">The model's joint names.</param>
        /// <param name="transformPaths">Every transform under the character ("" for the character itself).</param>
        /// <param name="missing">The joint names no transform carries, in joint order.</param>
        public static string?[] Resolve(IReadOnlyList<string> jointNames, IEnumerable<string> transformPaths, out List<string> missing)
        {
            if (jointNames == null) throw new ArgumentNullException(nameof(jointNames));
            if (transformPaths == null) throw new ArgumentNullException(nameof(transformPaths));
            var byName = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (string path in transformPaths)
            {
                if (path == null) continue;
                string name = LastName(path);
                if (!byName.TryGetValue(name, out string? existing) || Depth(path) < Depth(existing))
                {
                    byName[name] = path;
                }
            }

            var result = new string?[jointNames.Count];
            missing = new List<string>();
            for (int j = 0; j < result.Length; j++)
            {
                if (byName.TryGetValue(jointNames[j], out string? p))
                {
                    result[j] = p;
                }
                else
                {
                    missing.Add(jointNames[j]);
                }
            }

            return result;
        }

        private static string LastName(string path)
        {
            int slash = path.LastIndexOf('/');
            return slash < 0 ? path : path.Substring(slash + 1);
        }

        private static int Depth(string path)
        {
            if (path.Length == 0) return 0;
            int n = 1;
            foreach (char c in path)
            {
                if (c == '/') n++;
            }

            return n;
        }
    }
}
