using System.IO;
using System.Threading.Tasks;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.IO
{
    public class InputFileTests
    {
        [Test]
        public void MissingFilesAndFoldersAreNamedAsSuch()
        {
            using (var fs = new FileSystemFixtures())
            {
                Assert.That(Assert.Throws<InputPathException>(() => InputFile.Check(fs["none.bvh"], "a .bvh file"))!.Message, Is.EqualTo(fs["none.bvh"] + ": no such file; expected a .bvh file"));
                Assert.That(Assert.Throws<InputPathException>(() => BvhReader.Read(fs.Folder))!.Message, Is.EqualTo(fs.Folder + ": is a directory; expected a .bvh file"));
                InputFile.Check(fs.Write("a.bvh", "x"), "a .bvh file");
            }
        }

        [Test]
        public void ANamedPipeIsRefusedWithoutOpeningIt()
        {
            using (var fs = new FileSystemFixtures())
            {
                FileSystemFixtures.Unix("mkfifo", fs["pipe.bvh"]);
                // Opening a named pipe for reading blocks until a writer comes: the check must not open it.
                Task<string> read = Task.Run(() => Assert.Throws<InputPathException>(() => BvhReader.Read(fs["pipe.bvh"]))!.Message);
                Assert.That(read.Wait(30000), Is.True, "BvhReader.Read blocked on a named pipe");
                Assert.That(read.Result, Is.EqualTo(fs["pipe.bvh"] + ": is a named pipe (FIFO), not a regular file; expected a .bvh file"));
            }
        }

        [Test]
        public void DevicesAreRefused()
        {
            if (!File.Exists("/dev/zero")) Assert.Ignore("/dev/zero absent; skipping the device case");
            Assert.That(Assert.Throws<InputPathException>(() => BvhReader.Read("/dev/zero"))!.Message, Does.Contain("is a device"));
        }
    }
}
