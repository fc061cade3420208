using System.Collections.Generic;
using System.Linq;
using DeltaInterpolator.Core.Retargeting;

namespace DeltaInterpolator.Cli.Retargeting
{
    /// <summary>
    /// The conventions of Core's built-in joint maps as people call them, for help texts: read from
    /// <see cref="JointMap.BuiltIn"/> so that a map added there is named in every help at once.
    /// </summary>
    internal static class BuiltInMapNames
    {
        private static readonly Dictionary<string, string> Titles = new Dictionary<string, string>
        {
            ["lafan1"] = "LaFAN1",
            ["cmu"] = "CMU (MotionBuilder)",
            ["mixamo"] = "Mixamo",
            ["unity-humanoid"] = "Unity HumanBodyBones",
            ["poser"] = "Poser",
            ["biped"] = "3ds Max Biped (thighs under Bip01_Spine)",
            ["biped-pelvis"] = "3ds Max Biped (thighs under Bip01_Pelvis)",
        };

        /// <summary>Every built-in convention, e.g. "LaFAN1, CMU (MotionBuilder), Mixamo, Unity HumanBodyBones and Poser".</summary>
        public static string List
        {
            get
            {
                string[] names = JointMap.BuiltIn.Select(m => Titles.TryGetValue(m.Name, out string? title) ? title : m.Name).ToArray();
                return names.Length == 1 ? names[0] : string.Join(", ", names.Take(names.Length - 1)) + " and " + names[names.Length - 1];
            }
        }
    }
}
