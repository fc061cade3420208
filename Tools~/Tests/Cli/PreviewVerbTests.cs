using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Issue 30's preview options through the verb: <c>--map</c> picks the joints whose trails are drawn,
    /// <c>--frames</c> labels frames with the file's numbers, and hostile values of the new option are
    /// refused in one line with exit 2; <c>retarget --help</c> names every built-in convention.
    /// </summary>
    public sealed class PreviewVerbTests
    {
        private string _dir = "";

        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_01_01_jumps_turn.bvh");

        [SetUp]
        public void SetUp()
        {
            _dir = Path.Combine(Path.GetTempPath(), "preview-verb-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
            // SVG instead of PNG: the test reads the drawing's text (no Chromium needed).
            Environment.SetEnvironmentVariable("INBETWEEN_CHROMIUM", Path.Combine(_dir, "no-browser"));
        }

        [TearDown]
        public void TearDown()
        {
            Environment.SetEnvironmentVariable("INBETWEEN_CHROMIUM", null);
            Directory.Delete(_dir, true);
        }

        [Test]
        public void AMapChoosesTheTrailsAndFramesAreLabelledAsInTheFile()
        {
            // The CMU sample's hands and feet under other names: a map sends the trails to the wrists and toes instead.
            string map = Path.Combine(_dir, "map.json");
            File.WriteAllText(map, "{\"LeftHand\": \"LeftForeArm\", \"RightHand\": \"RightForeArm\", \"LeftFoot\": \"LeftToeBase\"}");
            string html = Path.Combine(_dir, "p.html"), png = Path.Combine(_dir, "p.png");
            CliRun run = CliHarness.Run("preview", "--truth", Sample, "--frames", "100-160", "--keys", "100,130,160", "--map", map, "--out", html, "--png", png);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            string svg = File.ReadAllText(Path.Combine(_dir, "p.svg"));
            Assert.That(svg, Does.Contain("trails: Hips, LeftForeArm, RightForeArm, LeftToeBase, RightFoot;"), "mapped joints, the rest by built-in names");
            Match footer = Regex.Match(svg, "poses at frames ([0-9, ]+);");
            Assert.That(footer.Groups[1].Value, Does.StartWith("100, ").And.Contain("130").And.EndWith("160"), "file frame numbers");
            Assert.That(File.ReadAllText(html), Does.Contain("\"firstFrame\":100"));

            // Without --map the trails follow the built-in names.
            CliRun plain = CliHarness.Run("preview", "--truth", Sample, "--frames", "100-160", "--out", html, "--png", png, "--force");
            Assert.That(plain.ExitCode, Is.EqualTo(0), plain.ToString());
            Assert.That(File.ReadAllText(Path.Combine(_dir, "p.svg")), Does.Contain("trails: Hips, LeftHand, RightHand, LeftFoot, RightFoot;"));
        }

        /// <summary>
        /// Issue 30: a real bake with keys every 0.5 s on a 60 fps clip (the 120 fps sample declared 60 fps,
        /// a key every 30 of its frames): its contact sheet draws poses between keys, in every row, labelled
        /// with the file's frame numbers.
        /// </summary>
        [Test]
        public void ABakesContactSheetShowsPosesBetweenItsKeys()
        {
            // The sample's first 302 frames: keys 1, 31, …, 301 are eleven, which the sheet used to thin to
            // every other key with the skipped key as the pose "between" them — only keys were drawn.
            string[] lines = File.ReadAllLines(Sample);
            int motion = Array.FindIndex(lines, l => l.StartsWith("Frame Time:", StringComparison.Ordinal));
            string clip = Path.Combine(_dir, "clip.bvh");
            File.WriteAllLines(clip, lines.Take(motion - 1).Append("Frames: 302").Append(lines[motion]).Concat(lines.Skip(motion + 1).Take(302)));
            string baked = Path.Combine(_dir, "b.bvh"), html = Path.Combine(_dir, "b.html"), png = Path.Combine(_dir, "b.png");
            CliRun run = CliHarness.Run("bake", clip, "--input-fps", "60", "--every", "30", "--from-frame", "1",
                "--out", baked, "--preview", html, "--png", png);
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            string svg = File.ReadAllText(Path.Combine(_dir, "b.svg"));
            Match footer = Regex.Match(svg, "poses at frames ([0-9, ]+);");
            Assert.That(footer.Success, Is.True);
            int[] poses = footer.Groups[1].Value.Split(',').Select(f => int.Parse(f.Trim(), System.Globalization.CultureInfo.InvariantCulture)).ToArray();
            // Keys at file frames 1, 31, 61, … and the last; the drawing's frames are the file's too.
            int[] between = poses.Where(f => (f - 1) % 30 != 0).ToArray();
            Assert.That(poses.Min(), Is.GreaterThanOrEqualTo(1), "labelled with the file's frame numbers (the bake starts at frame 1)");
            Assert.That(between.Length, Is.GreaterThanOrEqualTo(3), "poses between keys: " + footer.Groups[1].Value);
            Assert.That(poses.Max(), Is.EqualTo(301));
            foreach (string row in new[] { "SLERP", "Model" })
            {
                Assert.That(svg, Does.Contain(">" + row + "</text>"), row + "'s row");
            }
        }

        [Test]
        public void HostileMapsAreRefusedInOneLine()
        {
            string html = Path.Combine(_dir, "p.html");
            string lacking = Path.Combine(_dir, "other-rig.json");
            File.WriteAllText(lacking, "{\"LeftHand\": \"hand_l\"}");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", Sample, "--map", lacking, "--out", html), "maps LeftHand to 'hand_l', which cmu_01_01_jumps_turn.bvh lacks");
            Assert.That(File.Exists(html), Is.False, "nothing written");

            string broken = Path.Combine(_dir, "broken.json");
            File.WriteAllText(broken, "{\"LeftHand\": [}");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", Sample, "--map", broken, "--out", html), "broken.json");
            string empty = Path.Combine(_dir, "empty.json");
            File.WriteAllText(empty, "{\"LeftHand\": []}");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", Sample, "--map", empty, "--out", html), "maps to an empty array");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", Sample, "--map", _dir, "--out", html), _dir);
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", Sample, "--map", Path.Combine(_dir, "missing.json"), "--out", html), "missing.json");
            // A map is an input: never the output.
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", Sample, "--map", lacking, "--out", lacking, "--force"), "other-rig.json");
            Assert.That(File.ReadAllText(lacking), Is.EqualTo("{\"LeftHand\": \"hand_l\"}"));
            Assert.That(File.Exists(html), Is.False, "nothing written");
        }

        /// <summary>
        /// `info` at 80 columns (a pipe): one line a joint, none wider than the terminal (it took four lines a
        /// joint, 270 lines for a Mixamo rig). Before: channels and offsets wrapped into four lines.
        /// </summary>
        [Test]
        public void InfoListsOneLineAJointAt80Columns()
        {
            CliRun run = CliHarness.Run("info", Sample);
            CliHarness.AssertSuccess(run);
            string[] lines = run.Stdout.Split('\n');
            Assert.That(lines.Max(l => l.TrimEnd('\r').Length), Is.LessThanOrEqualTo(80), run.Stdout);
            string[] rows = lines.Where(l => Regex.IsMatch(l, "^│ +[0-9]+ │")).ToArray();
            Assert.That(rows, Has.Length.EqualTo(31), "one row a joint, each on one line:\n" + run.Stdout);
            Assert.That(rows[0], Does.Contain("Hips").And.Contain("pos XYZ rot ZYX"));
            Assert.That(rows.Count(r => r.Contains("LeftToeBase +")), Is.EqualTo(1), "End Sites marked");
            Assert.That(DeltaInterpolator.Cli.Verbs.InfoVerb.CompactChannels(new[] { Core.Bvh.BvhChannel.Zrotation, Core.Bvh.BvhChannel.Xrotation, Core.Bvh.BvhChannel.Yrotation }), Is.EqualTo("rot ZXY"));
            Assert.That(DeltaInterpolator.Cli.Verbs.InfoVerb.CompactChannels(new[] { Core.Bvh.BvhChannel.Xrotation, Core.Bvh.BvhChannel.Xposition }), Is.EqualTo("2 Xrotation Xposition"));
        }

        [Test]
        public void RetargetHelpNamesEveryBuiltInConvention()
        {
            CliRun run = CliHarness.Run("retarget", "--help");
            Assert.That(run.ExitCode, Is.EqualTo(0), run.ToString());
            string help = Regex.Replace(run.Stdout, "\\s+", " ");
            foreach (Core.Retargeting.JointMap map in Core.Retargeting.JointMap.BuiltIn)
            {
                string title = map.Name switch
                {
                    "lafan1" => "LaFAN1",
                    "cmu" => "CMU",
                    "mixamo" => "Mixamo",
                    "unity-humanoid" => "Unity HumanBodyBones",
                    "poser" => "Poser",
                    "biped" => "3ds Max Biped (thighs under Bip01_Spine)",
                    "biped-pelvis" => "3ds Max Biped (thighs under Bip01_Pelvis)",
                    _ => map.Name,
                };
                Assert.That(help, Does.Contain(title), $"the built-in map '{map.Name}'");
            }

            Assert.That(help, Does.Contain("Documentation~/retargeting.md"));
        }
    }
}
