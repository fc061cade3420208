using System.Diagnostics;
using System.IO;
using DeltaInterpolator.Cli.Scoring;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// <c>score --only</c> and a manifest's <c>files</c> globs follow Python's <c>fnmatch.fnmatchcase</c> (what
    /// <c>prepare</c> applies to the same manifests) and never fail with an exception: <c>[z-a]*</c> and <c>[!]</c>
    /// threw RegexParseException and a backtracking glob RegexMatchTimeoutException (exit 1, "this is a bug").
    /// </summary>
    public sealed class ScoreGlobsTests
    {
        // Expected values from Python 3's fnmatch.fnmatchcase.
        [TestCase("02_*", "02_01.bvh", true)]
        [TestCase("02_*", "nested/02_01.bvh", false)]
        [TestCase("*/02_*", "nested/02_01.bvh", true)]
        [TestCase("0?_0[1-3].bvh", "09_02.bvh", true)]
        [TestCase("0?_0[!1-3].bvh", "09_02.bvh", false)]
        [TestCase("0?_0[!1-3].bvh", "09_07.bvh", true)]
        [TestCase("[!]", "[!]", true)]
        [TestCase("[!]", "a", false)]
        [TestCase("[]]x", "]x", true)]
        [TestCase("[!]]x", "ax", true)]
        [TestCase("[a-]", "-", true)]
        [TestCase("[z-a]*", "zebra.bvh", false)]
        [TestCase("[!z-a]*", "zebra.bvh", true)]
        [TestCase("[abc", "[abc", true)]
        [TestCase("*.BVH", "a.bvh", false)]
        [TestCase("a**b", "ab", true)]
        [TestCase("", "", true)]
        public void GlobsMatchAsPythonsFnmatch(string glob, string name, bool expected)
        {
            Assert.That(DataManifest.Glob(glob, name), Is.EqualTo(expected));
        }

        [Test]
        public void ABacktrackingGlobMatchesInBoundedTime()
        {
            string glob = string.Concat(System.Linq.Enumerable.Repeat("*a", 30)) + "*b";
            string name = new string('a', 5000);
            var clock = Stopwatch.StartNew();
            Assert.That(DataManifest.Glob(glob, name), Is.False);
            Assert.That(DataManifest.Glob(glob, name + "b"), Is.True);
            Assert.That(clock.Elapsed.TotalSeconds, Is.LessThan(5), "at most (pattern × name) steps");
        }

        [Test]
        public void HostileOnlyGlobsAreOneLine()
        {
            using var temp = new TempFolder();
            string data = Path.Combine(temp.Path, "data");
            temp.Write("data/" + new string('a', 200) + ".bvh", "not read: no file is selected");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "score", data, "--every", "60", "--only", "[z-a]*"), "reversed range z-a");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "score", data, "--every", "60", "--only", "[!]"), "no BVH files");
            string backtracking = string.Concat(System.Linq.Enumerable.Repeat("*a", 30)) + "*b";
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "score", data, "--every", "60", "--only", backtracking), "no BVH files");
        }
    }
}
