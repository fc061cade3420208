using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// A seeded mutation fuzzer of the BVH reader through the CLI's entry point (<c>inbetween info</c>,
    /// in process): byte flips, deletions, duplicated lines, huge numbers, NaN and infinity text,
    /// truncation, CR-only line endings, deep nesting and control bytes, applied to a synthetic clip
    /// (always) and to cut-down LaFAN1 and CMU files (when ../shared/data is there). Every mutant must
    /// give exit 0 with a clean stdout, or exit 2 with exactly one safe error line — never a crash, a
    /// hang, a stack trace or exit 1.
    /// </summary>
    [NonParallelizable]
    public class BvhFuzzTests
    {
        private const int SyntheticMutants = 150;
        private const int DataMutants = 100;

        [Test]
        public void SyntheticClipMutants()
        {
            Fuzz("synthetic", Encoding.ASCII.GetBytes(CliHarness.WalkClip(120)), seed: 8001, SyntheticMutants);
        }

        [Test]
        public void Lafan1Mutants()
        {
            string dir = TestEnvironment.RequireLafan1();
            string path = Path.Combine(dir, "walk4_subject1.bvh");
            if (!File.Exists(path)) Assert.Ignore($"{path} absent; skipping the LaFAN1 fuzz cases (the synthetic ones still run)");
            Fuzz("lafan1", FirstFrames(File.ReadAllBytes(path), 200), seed: 8002, DataMutants);
        }

        [Test]
        public void CmuMutants()
        {
            string? root = TestEnvironment.RepositoryRoot;
            string path = root == null ? "../shared/data/cmu/01_01.bvh" : Path.GetFullPath(Path.Combine(root, "..", "shared", "data", "cmu", "01_01.bvh"));
            if (!File.Exists(path)) Assert.Ignore($"CMU data not found at {path}; skipping the CMU fuzz cases (the synthetic ones still run)");
            Fuzz("cmu", FirstFrames(File.ReadAllBytes(path), 200), seed: 8003, DataMutants);
        }

        /// <summary>The file cut to its first <paramref name="frames"/> motion lines, with Frames: fixed (in memory).</summary>
        private static byte[] FirstFrames(byte[] data, int frames)
        {
            string[] lines = Encoding.UTF8.GetString(data).Replace("\r\n", "\n").Split('\n');
            int header = Array.FindIndex(lines, l => l.StartsWith("Frame Time:", StringComparison.Ordinal));
            Assert.That(header, Is.GreaterThan(0), "a BVH file with a Frame Time: line");
            var kept = new List<string>(lines.Take(header + 1));
            int frameLine = Array.FindIndex(lines, l => l.StartsWith("Frames:", StringComparison.Ordinal));
            kept[frameLine] = "Frames: " + frames;
            kept.AddRange(lines.Skip(header + 1).Take(frames));
            return Encoding.UTF8.GetBytes(string.Join("\n", kept) + "\n");
        }

        private static void Fuzz(string name, byte[] original, int seed, int count)
        {
            var random = new Random(seed);
            using var temp = new TempFolder();
            string path = temp[name + ".bvh"];
            var outcomes = new Dictionary<string, int>();
            var clock = Stopwatch.StartNew();

            File.WriteAllBytes(path, original);
            CliHarness.AssertSuccess(CliHarness.Run("info", path));

            for (int i = 0; i < count; i++)
            {
                string kind;
                byte[] mutant = Mutate(original, random, out kind);
                File.WriteAllBytes(path, mutant);
                CliRun run = CliHarness.RunWithin(60, "info", path);
                string what = $"{name} mutant {i} (seed {seed}, {kind})";
                if (run.ExitCode == 0)
                {
                    CliHarness.AssertSuccess(run);
                }
                else
                {
                    Assert.That(run.ExitCode, Is.EqualTo(2), what + ": " + run);
                    string line = CliHarness.AssertOneErrorLine(run);
                    Assert.That(line, Does.StartWith(path), what + ": the message names the file");
                }

                string key = kind + (run.ExitCode == 0 ? " → exit 0" : " → exit 2");
                outcomes[key] = outcomes.TryGetValue(key, out int n) ? n + 1 : 1;
            }

            TestContext.Progress.WriteLine($"{name}: {count} mutants in {clock.Elapsed.TotalSeconds:0.0} s: " + string.Join(", ", outcomes.OrderBy(p => p.Key, StringComparer.Ordinal).Select(p => $"{p.Key} {p.Value}")));
        }

        private static readonly string[] HugeNumbers = { "1e308", "-1e308", "1e400", "-1e999999999", "123456789012345678901234567890123456789", "4.9e-325", "0x1F", "1e", "--5", "1.2.3" };
        private static readonly string[] NonFinite = { "NaN", "nan", "-inf", "Infinity", "+Infinity", "∞", "-nan(ind)" };
        private static readonly string[] ControlBytes = { "\u001b[2J", "\u001b]0;pwned\u0007", "\u0000", "\u0007", "\u0008\u0008", "\u009b31m", "\u202e", "\u0085" };

        private static byte[] Mutate(byte[] original, Random random, out string kind)
        {
            var bytes = new List<byte>(original);
            string text = Encoding.UTF8.GetString(original);
            string[] lines = text.Split('\n');
            switch (random.Next(10))
            {
                case 0:
                    kind = "byte flips";
                    for (int k = random.Next(1, 6); k > 0; k--) bytes[random.Next(bytes.Count)] = (byte)random.Next(256);
                    return bytes.ToArray();
                case 1:
                {
                    kind = "deletion";
                    int start = random.Next(bytes.Count);
                    bytes.RemoveRange(start, Math.Min(bytes.Count - start, random.Next(1, 200)));
                    return bytes.ToArray();
                }
                case 2:
                {
                    kind = "duplicated line";
                    var list = lines.ToList();
                    int at = random.Next(list.Count);
                    for (int k = random.Next(1, 4); k > 0; k--) list.Insert(at, list[at]);
                    return Encoding.UTF8.GetBytes(string.Join("\n", list));
                }
                case 3:
                    kind = "huge number";
                    return Encoding.UTF8.GetBytes(ReplaceNumber(lines, random, HugeNumbers[random.Next(HugeNumbers.Length)]));
                case 4:
                    kind = "NaN/inf text";
                    return Encoding.UTF8.GetBytes(ReplaceNumber(lines, random, NonFinite[random.Next(NonFinite.Length)]));
                case 5:
                    kind = "truncation";
                    return original.Take(random.Next(original.Length)).ToArray();
                case 6:
                    kind = "CR-only line endings";
                    return Encoding.UTF8.GetBytes(random.Next(2) == 0 ? text.Replace("\n", "\r") : text.Replace("\n", "\r\n").Replace("\r\n\r\n", "\r\r"));
                case 7:
                {
                    kind = "deep nesting";
                    int depth = random.Next(50, 3000);
                    var nest = new StringBuilder();
                    for (int k = 0; k < depth; k++) nest.Append("JOINT Fuzz").Append(k).Append("\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Yrotation Xrotation\n");
                    nest.Append(random.Next(3) == 0 ? "" : string.Concat(Enumerable.Repeat("}\n", random.Next(depth - 1, depth + 2))));
                    int firstJoint = text.IndexOf("\tJOINT", StringComparison.Ordinal);
                    if (firstJoint < 0) firstJoint = text.IndexOf("JOINT", StringComparison.Ordinal);
                    return Encoding.UTF8.GetBytes(text.Insert(Math.Max(0, firstJoint), nest.ToString()));
                }
                case 8:
                {
                    kind = "control bytes";
                    string insert = ControlBytes[random.Next(ControlBytes.Length)];
                    int at = random.Next(2) == 0 ? text.IndexOf("JOINT ", StringComparison.Ordinal) + 7 : random.Next(text.Length);
                    return Encoding.UTF8.GetBytes(text.Insert(Math.Max(0, Math.Min(at, text.Length)), insert));
                }
                default:
                {
                    kind = "deleted line";
                    var list = lines.ToList();
                    list.RemoveAt(random.Next(list.Count));
                    return Encoding.UTF8.GetBytes(string.Join("\n", list));
                }
            }
        }

        /// <summary>Replaces one number (in the hierarchy or the motion) with <paramref name="replacement"/>.</summary>
        private static string ReplaceNumber(string[] lines, Random random, string replacement)
        {
            var list = lines.ToArray();
            for (int attempt = 0; attempt < 50; attempt++)
            {
                int line = random.Next(list.Length);
                string[] words = list[line].Split(' ', '\t');
                var numeric = Enumerable.Range(0, words.Length).Where(k => words[k].Length > 0 && (char.IsDigit(words[k][0]) || words[k][0] == '-')).ToArray();
                if (numeric.Length == 0) continue;
                words[numeric[random.Next(numeric.Length)]] = replacement;
                list[line] = string.Join(" ", words);
                break;
            }

            return string.Join("\n", list);
        }
    }
}
