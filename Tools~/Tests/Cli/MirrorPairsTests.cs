using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text.Json;
using DeltaInterpolator.Cli.Scoring;
using DeltaInterpolator.Core.Skeletons;
using DeltaInterpolator.Evaluation.Baking;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// The Python/C# mirror, checked on the C# side (issue 26 item 5): every C# type in
    /// <c>Training/Python~/mirror-pairs.json</c> exists in the package's assemblies (found by its name, in any
    /// namespace, so moving it between rooms is free and renaming it is not) and every member named on it exists.
    /// <c>test_mirror_pairs.py</c> checks the Python side of the same rows.
    /// </summary>
    public sealed class MirrorPairsTests
    {
        private const BindingFlags Everything = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static | BindingFlags.Instance | BindingFlags.DeclaredOnly;

        /// <summary>Core, Evaluation and the CLI: where the mirrored types live.</summary>
        private static readonly Assembly[] Assemblies = { typeof(Skeleton).Assembly, typeof(FootSkating).Assembly, typeof(DataManifest).Assembly };

        private static IEnumerable<TestCaseData> Pairs()
        {
            string path = Path.Combine(TestEnvironment.RepositoryRoot ?? ".", "Training", "Python~", "mirror-pairs.json");
            if (!File.Exists(path)) yield break;
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(path));
            foreach (JsonElement pair in doc.RootElement.GetProperty("pairs").EnumerateArray())
            {
                string python = pair.GetProperty("python").GetString()!;
                foreach (JsonElement c in pair.GetProperty("csharp").EnumerateArray())
                {
                    yield return new TestCaseData(c.GetString()!).SetName($"{python} mirrors {c.GetString()}");
                }
            }
        }

        [Test]
        public void TheTableIsRead()
        {
            Assert.That(Pairs().Count(), Is.GreaterThanOrEqualTo(30), "Training/Python~/mirror-pairs.json");
        }

        [TestCaseSource(nameof(Pairs))]
        public void EveryCSharpNameInTheMirrorTableExists(string name)
        {
            Assert.That(Exists(name), Is.True, $"{name} is gone from the package's assemblies; rename it in Training/Python~/mirror-pairs.json (and the Python docstrings) too");
        }

        [Test]
        public void ARenamedTypeOrMemberIsCaught()
        {
            Assert.That(Exists("OutputDecoder.Rotation"), Is.True);
            Assert.That(Exists("OutputDecoder.RotationRenamed"), Is.False);
            Assert.That(Exists("OutputDecoderRenamed"), Is.False);
        }

        private static bool Exists(string name)
        {
            string[] parts = name.Split('.');
            List<Type> types = Assemblies.SelectMany(a => a.GetTypes()).Where(t => t.Name == parts[0]).ToList();
            if (parts.Length == 1) return types.Count > 0;
            return types.Any(t => t.GetMember(parts[1], Everything).Length > 0);
        }
    }
}
