using System;
using System.Collections.Generic;
using System.IO;
using System.Threading.Tasks;
using DeltaInterpolator.Cli.Scoring;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// <c>score</c> reads each real folder of its data once: a directory link back to the folder (<c>l -&gt; .</c>)
    /// scored every file 17 times (once per path up to the old depth limit), and three links looping among
    /// the folders made 3^16 paths (minutes, growing memory).
    /// </summary>
    public sealed class ScoreVisitsEachFolderOnceTests
    {
        private static string Sample => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_09_12_walk_navigate.bvh");

        [Test]
        public void ALinkBackToTheFolderScoresEachFileOnce()
        {
            using var temp = new TempFolder();
            string data = Path.Combine(temp.Path, "data");
            Directory.CreateDirectory(Path.Combine(data, "sub"));
            File.Copy(Sample, Path.Combine(data, "01_01.bvh"));
            Link(Path.Combine(data, "l"), ".");
            Link(Path.Combine(data, "sub", "up"), "..");

            Assert.That(Names(data), Is.EqualTo(new[] { "01_01.bvh" }));
            CliRun run = CliHarness.RunWithin(120, "score", data, "--every", "60");
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("all 1 files"), run.ToString());
        }

        [Test]
        public void LoopingLinksAreWalkedInLinearTime()
        {
            using var temp = new TempFolder();
            string data = Path.Combine(temp.Path, "data");
            foreach (string folder in new[] { "a", "b", "c" })
            {
                Directory.CreateDirectory(Path.Combine(data, folder));
                temp.Write("data/" + folder + "/" + folder + ".bvh", "not read here");
            }

            // Each folder links to the other two and to the top: every path may go on forever.
            Link(Path.Combine(data, "a", "to-b"), "../b");
            Link(Path.Combine(data, "b", "to-c"), "../c");
            Link(Path.Combine(data, "c", "to-a"), "../a");
            Link(Path.Combine(data, "a", "top"), "..");
            Link(Path.Combine(data, "b", "top"), "..");
            Link(Path.Combine(data, "c", "top"), "..");
            // A link to a folder outside the data is still followed (once): only repeats are dropped.
            string outside = Path.Combine(temp.Path, "outside");
            Directory.CreateDirectory(outside);
            temp.Write("outside/o.bvh", "not read here");
            Link(Path.Combine(data, "more"), outside);

            Task<List<string>> names = Task.Run(() => Names(data));
            Assert.That(names.Wait(TimeSpan.FromSeconds(30)), Is.True, "the walk did not end within 30 s");
            Assert.That(names.Result, Is.EqualTo(new[] { "a/a.bvh", "b/b.bvh", "c/c.bvh", "more/o.bvh" }), "each real folder under its shortest name");
        }

        private static List<string> Names(string data)
        {
            var names = new List<string>();
            foreach (DataManifest.Entry e in DataManifest.Open(data).Entries(Array.Empty<string>())) names.Add(e.Name);
            return names;
        }

        private static void Link(string path, string target)
        {
            try
            {
                Directory.CreateSymbolicLink(path, target);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                Assert.Ignore("this system does not let a test make directory links: " + e.Message);
            }
        }
    }
}
