using System.Collections.Generic;
using System.Globalization;
using System.Text;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Skeletons;
using Spectre.Console;

namespace DeltaInterpolator.Cli.Verbs
{
    /// <summary>
    /// What a joint map says that the verbs using it (<c>retarget --map</c>, <c>bake --map</c>) show rather
    /// than ignore: keys that are not joints of the target skeleton, and name lists kept to one bounded line.
    /// </summary>
    internal static class MapWarnings
    {
        /// <summary>
        /// Prints one warning naming the keys of <paramref name="map"/> (read from <paramref name="mapPath"/>)
        /// that <paramref name="target"/> lacks, when there are any; they are ignored.
        /// </summary>
        public static void UnknownTargets(JointMap map, Skeleton target, string mapPath)
        {
            IReadOnlyList<string> unknown = map.TargetsNotIn(target);
            if (unknown.Count == 0) return;
            AnsiConsole.MarkupLine("[yellow]warning:[/] " + Markup.Escape(TerminalText.Safe(string.Format(CultureInfo.InvariantCulture,
                "{0}: {1} key{2} of the map {3} not a joint of the model's skeleton and {4} ignored: {5}; expected model joint names such as {6}",
                mapPath, unknown.Count, unknown.Count == 1 ? "" : "s", unknown.Count == 1 ? "is" : "are", unknown.Count == 1 ? "is" : "are",
                NameList(unknown), target.JointCount > 1 ? target.Names[0] + ", " + target.Names[1] : target.Names[0]), TerminalText.LineLength)));
        }

        /// <summary>Names joined by ", ", each clipped and made terminal-safe, the whole list at most one message line (a count of the rest).</summary>
        public static string NameList(IReadOnlyList<string> names)
        {
            var sb = new StringBuilder();
            for (int i = 0; i < names.Count; i++)
            {
                string name = TerminalText.Safe(names[i], TerminalText.NameLength);
                if (sb.Length + name.Length > TerminalText.LineLength / 2)
                {
                    sb.Append(string.Format(CultureInfo.InvariantCulture, "… and {0:N0} more", names.Count - i));
                    break;
                }

                if (i > 0) sb.Append(", ");
                sb.Append(name);
            }

            return sb.ToString();
        }
    }
}
