using System;
using System.IO;
using System.Text;
using DeltaInterpolator.Core.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.IO
{
    public class OutputFileTests
    {
        [Test]
        public void AWriteThatThrowsHalfWayLeavesTheOldFileByteIdentical()
        {
            using (var fs = new FileSystemFixtures())
            {
                string path = fs.Write("out.json", "{\"old\": [1, 2, 3]}\n");
                byte[] before = File.ReadAllBytes(path);
                var e = Assert.Throws<IOException>(() => OutputFile.Write(path, stream =>
                {
                    byte[] half = Encoding.UTF8.GetBytes("{\"new\": [");
                    stream.Write(half, 0, half.Length);
                    throw new IOException("interrupted (simulated)");
                }))!;
                Assert.That(e.Message, Does.Contain("simulated"));
                Assert.That(File.ReadAllBytes(path), Is.EqualTo(before));
                Assert.That(fs.Files, Is.EqualTo(new[] { path }), "the temporary file is removed");

                OutputFile.WriteAllText(path, "{\"new\": true}\n");
                Assert.That(File.ReadAllText(path), Is.EqualTo("{\"new\": true}\n"));
                Assert.That(fs.Files, Is.EqualTo(new[] { path }));
            }
        }

        [Test]
        public void ANewFileIsNotCreatedWhenTheWriteFails()
        {
            using (var fs = new FileSystemFixtures())
            {
                string path = fs["sub/new.bin"];
                Assert.Throws<InvalidOperationException>(() => OutputFile.Write(path, s =>
                {
                    s.WriteByte(1);
                    throw new InvalidOperationException("failed");
                }));
                Assert.That(File.Exists(path), Is.False);
                OutputFile.WriteAllBytes(path, new byte[] { 1, 2, 3 });
                Assert.That(File.ReadAllBytes(path), Is.EqualTo(new byte[] { 1, 2, 3 }));
            }
        }

        [Test]
        public void CheckRefusesExistingFilesWithoutForceFoldersAndInputs()
        {
            using (var fs = new FileSystemFixtures())
            {
                string existing = fs.Write("a.json", "x");
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(existing, false))!.Message, Does.Contain("already exists; expected a new path, or --force"));
                Assert.That(OutputFile.Check(existing, true), Is.EqualTo(Path.GetFullPath(existing)));
                Assert.That(OutputFile.Check(fs["new.json"], false), Is.EqualTo(Path.GetFullPath(fs["new.json"])));
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(fs.Folder, true))!.Message, Does.Contain("is a directory"));
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(existing, true, "other.bvh", existing))!.Message, Does.Contain("is also an input"));
                string respelled = Path.Combine(fs.Folder, "sub", "..", "a.json");
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(respelled, true, existing))!.Message, Does.Contain("is also an input"));
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(Path.Combine(existing, "inside.json"), true))!.Message, Does.Contain("is a file"));
            }
        }

        [Test]
        public void CheckFindsInputsThroughSymbolicAndHardLinks()
        {
            using (var fs = new FileSystemFixtures())
            {
                string input = fs.Write("stats.json", "{}");
                FileSystemFixtures.Unix("ln", "-s", input, fs["symbolic.json"]);
                FileSystemFixtures.Unix("ln", input, fs["hard.json"]);
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(fs["symbolic.json"], true, input))!.Message, Does.Contain("is also an input"));
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(fs["hard.json"], true, input))!.Message, Does.Contain("is also an input"));
                Assert.That(OutputFile.Check(fs.Write("unrelated.json", "{}"), true, input), Is.Not.Empty, "a different file with the same content is not the input");
            }
        }

        [Test]
        public void CheckRefusesNamedPipesAndUnwritableFolders()
        {
            using (var fs = new FileSystemFixtures())
            {
                FileSystemFixtures.Unix("mkfifo", fs["pipe"]);
                Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check(fs["pipe"], true))!.Message, Does.Contain("named pipe"));
                if (Directory.Exists("/proc/self"))
                {
                    Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check("/proc/deltainterp.json", true))!.Message, Does.Contain("cannot write in the folder /proc; expected a writable folder"));
                }

                if (File.Exists("/dev/null"))
                {
                    Assert.That(Assert.Throws<OutputPathException>(() => OutputFile.Check("/dev/null", true))!.Message, Does.Contain("is a device"));
                }
            }
        }
    }
}
