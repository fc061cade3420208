using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// <c>bake</c>'s default foot locking on a leg that is not a plain thigh → knee → ankle chain: a twist joint in the
    /// thigh is locked through (it rides along), and a knee the joint map synthesizes (<c>{"LeftLeg": null}</c>) skips
    /// locking with one warning. Both exited 1 with "this is a bug" and API names.
    /// </summary>
    public sealed class BakeLocksFeetOnAnyLegTests
    {
        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        [Test]
        public void ATwistJointInTheThighIsLockedThrough()
        {
            using var temp = new TempFolder();
            string twisted = temp.Write("twisted.bvh", WithLeftThighTwist(File.ReadAllText(Sample)));
            CliRun run = CliHarness.RunWithin(300, "bake", twisted, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--out", temp["o.bvh"]);
            CliHarness.AssertSuccess(run);
            string text = Regex.Replace(run.Stdout, @"\s+", " ");
            Assert.That(text, Does.Contain("feet: locked"), run.ToString());
            Assert.That(text, Does.Not.Contain("warning:"), run.ToString());
        }

        [Test]
        public void AKneeTheMapSynthesizesSkipsLockingWithOneWarning()
        {
            using var temp = new TempFolder();
            string map = temp.Write("map.json", "{\"LeftLeg\": null}");
            CliRun run = CliHarness.RunWithin(300, "bake", Sample, "--every", "60", "--from-frame", "1", "--reference-frame", "0", "--map", map, "--out", temp["o.bvh"]);
            CliHarness.AssertSuccess(run);
            string text = Regex.Replace(run.Stdout, @"\s+", " ");
            Assert.That(Regex.Matches(text, "warning: foot locking skipped").Count, Is.EqualTo(1), run.ToString());
            Assert.That(text, Does.Contain("LeftLeg"), run.ToString());
            Assert.That(text, Does.Contain("feet: not locked on this rig"), run.ToString());
            Assert.That(File.Exists(temp["o.bvh"]), Is.True);
        }

        /// <summary>
        /// The CMU clip with a joint halfway down the left thigh (LeftUpLegTwist, still: the same motion): a
        /// rig of another shape, on which the knee's parent is not the thigh.
        /// </summary>
        private static string WithLeftThighTwist(string bvh)
        {
            const string knee = "\t\t\tJOINT LeftLeg\n\t\t\t{\n\t\t\t\tOFFSET 2.57982 -7.08799 0.00000\n";
            Assert.That(bvh.Replace("\r\n", "\n"), Does.Contain(knee), "the sample's left knee as this test knows it");
            string text = bvh.Replace("\r\n", "\n");
            int at = text.IndexOf(knee, System.StringComparison.Ordinal);
            int close = text.IndexOf("\n\t\t\t}\n", at, System.StringComparison.Ordinal) + "\n\t\t\t}\n".Length;
            string block = text.Substring(at, close - at).Replace("OFFSET 2.57982 -7.08799 0.00000", "OFFSET 1.28991 -3.543995 0.00000");
            string twist = "\t\t\tJOINT LeftUpLegTwist\n\t\t\t{\n\t\t\t\tOFFSET 1.28991 -3.543995 0.00000\n\t\t\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n" + block + "\t\t\t}\n";
            text = text.Substring(0, at) + twist + text.Substring(close);
            // Motion: LeftUpLegTwist's three channels follow LeftUpLeg's (channels 9-11), after the root's 6 and LHipJoint's 3.
            string[] parts = text.Split(new[] { "Frame Time:" }, System.StringSplitOptions.None);
            string[] lines = parts[1].Split('\n');
            for (int i = 1; i < lines.Length; i++)
            {
                string[] v = lines[i].Split(new[] { ' ', '\t' }, System.StringSplitOptions.RemoveEmptyEntries);
                if (v.Length < 12) continue;
                lines[i] = string.Join(" ", v.Take(12).Concat(new[] { "0", "0", "0" }).Concat(v.Skip(12)));
            }

            return parts[0] + "Frame Time:" + string.Join("\n", lines);
        }
    }
}
