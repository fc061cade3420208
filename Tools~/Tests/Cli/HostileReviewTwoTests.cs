using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using DeltaInterpolator.Cli;
using DeltaInterpolator.Core.IO;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// Regression tests for the second hostile review (issue 16): each case ran the real tool in process on
    /// hand-made files and broke the contract (exit 2 and one line `FILE:LINE: what; expected`; nothing
    /// existing changed; bounded time and memory; nothing raw on the terminal) before the fix. The class
    /// number of the issue is in each test's comment.
    /// </summary>
    [NonParallelizable]
    public class HostileReviewTwoTests
    {
        private static string Model => Path.Combine(TestEnvironment.RepositoryRoot!, "Runtime", "Models", "DeltaInterpolator-LaFAN1.onnx");

        private static string CmuClip => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_01_01_jumps_turn.bvh");

        private static void RequireShipped()
        {
            if (TestEnvironment.RepositoryRoot == null || !File.Exists(Model) || !File.Exists(CmuClip))
            {
                Assert.Ignore("the shipped model or the demo clip is absent; skipping");
            }
        }

        /// <summary>The demo clip's first <paramref name="frames"/> frames, with one root value replaced at <paramref name="frame"/>.</summary>
        private static string CmuExcerpt(int frames, int frame = -1, string value = "")
        {
            string[] lines = File.ReadAllLines(CmuClip);
            int motion = Array.IndexOf(lines, "MOTION");
            var sb = new StringBuilder();
            for (int i = 0; i <= motion; i++) sb.Append(lines[i]).Append('\n');
            sb.Append("Frames: ").Append(frames).Append('\n').Append(lines[motion + 2]).Append('\n');
            for (int f = 0; f < frames; f++)
            {
                string row = lines[motion + 3 + f];
                if (f == frame)
                {
                    string[] v = row.Split(' ', StringSplitOptions.RemoveEmptyEntries);
                    v[0] = value;
                    row = string.Join(" ", v);
                }

                sb.Append(row).Append('\n');
            }

            return sb.ToString();
        }

        private static string[] TemporaryFiles(string folder) => Directory.GetFiles(folder, "*.tmp", SearchOption.AllDirectories);

        // 1. The contact sheet's SVG fallback was checked only after the work, with --force, and not against
        // inputs or other outputs: it replaced an input and the page just written.
        [Test]
        public void TheSvgFallbackOfTheContactSheetNeverReplacesAnInputOrAnotherOutput()
        {
            using var temp = new TempFolder();
            string clip = temp.Write("clip.svg", CliHarness.WalkClip(10));
            byte[] before = File.ReadAllBytes(clip);
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", clip, "--out", temp["page.html"], "--png", temp["clip.png"], "--force"), "clip.svg");
            Assert.That(File.ReadAllBytes(clip), Is.EqualTo(before), "the input must stay byte-identical");

            string bvh = temp.Write("walk.bvh", CliHarness.WalkClip(10));
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", bvh, "--out", temp["page.svg"], "--png", temp["page.png"]), "page.svg");
            Assert.That(File.Exists(temp["page.svg"]), Is.False, "refused before the page was written");

            // An existing fallback SVG is refused up front without --force, whether or not Chromium is there.
            string old = temp.Write("sheet.svg", "old");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", bvh, "--out", temp["p2.html"], "--png", temp["sheet.png"]), "sheet.svg");
            Assert.That(File.ReadAllText(old), Is.EqualTo("old"));
            Assert.That(File.Exists(temp["p2.html"]), Is.False);
        }

        // 3. Two runs writing the same new path without --force both succeeded; the later silently replaced the other.
        [Test]
        public void ANewOutputThatAppearedMeanwhileIsNeverReplaced()
        {
            using var temp = new TempFolder();
            string path = temp["out.bvh"];
            OutputFile.Check(path, false);
            File.WriteAllText(path, "the other run's file"); // another run finished first
            var e = Assert.Throws<OutputPathException>(() => OutputFile.WriteAllText(path, "ours"))!;
            Assert.That(e.Message, Does.Contain("appeared while this command ran"));
            Assert.That(e.Message, Does.Contain("; expected"));
            Assert.That(File.ReadAllText(path), Is.EqualTo("the other run's file"));
            Assert.That(TemporaryFiles(temp.Path), Is.Empty, "no temporary file left");

            // With --force (checked as existing) the file is replaced, as asked.
            OutputFile.Check(path, true);
            OutputFile.WriteAllText(path, "ours");
            Assert.That(File.ReadAllText(path), Is.EqualTo("ours"));

            // A new path still missing at the end is created as before.
            string fresh = temp["fresh.bvh"];
            OutputFile.Check(fresh, false);
            OutputFile.WriteAllText(fresh, "new");
            Assert.That(File.ReadAllText(fresh), Is.EqualTo("new"));
        }

        // 4. NaN or infinity reached a written BVH with exit 0 (bake of a file with a 1e308 root value at a
        // key; retarget --scale 1e308 wrote Infinity).
        [Test]
        public void NonFiniteMotionIsNeverWritten()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("huge.bvh", CmuExcerpt(241, 120, "1e308"));
            string output = temp.Write("out.bvh", "good old output\n");
            CliRun bake = CliHarness.Run("bake", input, "--every", "40", "--out", output, "--force", "--model", Model);
            CliHarness.AssertOneErrorLine(bake, "huge.bvh: ");
            Assert.That(File.ReadAllText(output), Is.EqualTo("good old output\n"), "the old output must stay");
            Assert.That(TemporaryFiles(temp.Path), Is.Empty);

            string plain = temp.Write("plain.bvh", CmuExcerpt(121));
            string retargeted = temp["scaled.bvh"];
            CliRun scaled = CliHarness.Run("retarget", plain, "--to", "model", "--out", retargeted, "--scale", "1e308", "--model", Model);
            string line = CliHarness.AssertOneErrorLine(scaled, "not a finite number");
            Assert.That(File.Exists(retargeted), Is.False, line);

            // The writer itself refuses a NaN before a byte reaches the file.
            Core.Bvh.BvhAnimation walk = Core.Bvh.BvhReader.Parse(CliHarness.WalkClip(3), "walk.bvh");
            walk.Motion.LocalRotations[5] = double.NaN;
            string target = temp.Write("nan.bvh", "old");
            Assert.Throws<Core.DataFormatException>(() => Core.Bvh.BvhWriter.Write(walk, target));
            Assert.That(File.ReadAllText(target), Is.EqualTo("old"));
        }

        // 5. pack followed symbolic links out of the package (/etc/passwd packed; /dev/zero read forever)
        // and 15. blocked forever on a named pipe .meta or package.json.
        [Test]
        public void PackRefusesLinksOutOfThePackageAndFilesThatAreNotRegular()
        {
            if (OperatingSystem.IsWindows()) Assert.Ignore("symbolic links and named pipes: Unix");
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            string secret = temp.Write("secret.txt", "root:x:0:0\n");
            File.CreateSymbolicLink(Path.Combine(root, "Runtime", "Leak.txt"), secret);
            temp.Write("pkg/Runtime/Leak.txt.meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000aa\n");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root, "--out", temp["out"]), "outside the package");
            Assert.That(Directory.Exists(temp["out"]) && Directory.GetFiles(temp["out"]).Length > 0, Is.False, "nothing written");

            File.Delete(Path.Combine(root, "Runtime", "Leak.txt"));
            File.CreateSymbolicLink(Path.Combine(root, "Runtime", "Leak.txt"), "/dev/zero");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root, "--out", temp["out"]), "Leak.txt");

            File.Delete(Path.Combine(root, "Runtime", "Leak.txt"));
            File.Delete(Path.Combine(root, "Runtime", "Leak.txt.meta"));
            File.Delete(Path.Combine(root, "Runtime", "Motion.cs.meta"));
            CliHarness.MakeFifo(Path.Combine(root, "Runtime", "Motion.cs.meta"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root, "--out", temp["out"]), "named pipe");

            string root2 = SmallPackage(temp, "pkg2");
            File.Delete(Path.Combine(root2, "package.json"));
            CliHarness.MakeFifo(Path.Combine(root2, "package.json"));
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "pack", "--root", root2, "--out", temp["out2"]), "named pipe");

            // A link inside the package to a file of the package is packed (its content).
            string root3 = SmallPackage(temp, "pkg3");
            File.CreateSymbolicLink(Path.Combine(root3, "Runtime", "Alias.cs"), Path.Combine(root3, "Runtime", "Motion.cs"));
            temp.Write("pkg3/Runtime/Alias.cs.meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ab\n");
            CliHarness.AssertSuccess(CliHarness.RunWithin(60, "pack", "--root", root3, "--out", temp["out3"]));
        }

        // 6. Archive paths that escape: a name with '\..\', a package name of '../../x', control characters.
        [TestCase("name", "../../escape")]
        [TestCase("name", "com.example/../../x")]
        [TestCase("version", "1.0.0/../../../x")]
        public void PackRefusesAManifestThatWouldMakePathsClimbOut(string field, string value)
        {
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg", field == "name" ? value : "com.example.pack", field == "version" ? value : "1.2.3");
            CliRun run = CliHarness.Run("pack", "--root", root, "--out", temp["out/deep"]);
            CliHarness.AssertOneErrorLine(run, "\"" + field + "\"");
            Assert.That(Directory.GetFiles(temp.Path, "*.tgz", SearchOption.AllDirectories), Is.Empty);
            Assert.That(Directory.GetFiles(temp.Path, "*.unitypackage", SearchOption.AllDirectories), Is.Empty);
        }

        [TestCase("Evil\\..\\..\\x.cs", "'\\'")]
        [TestCase("Bell\u0007\u001b]0;t.cs", "control")]
        public void PackRefusesFileNamesAnArchiveCannotHoldSafely(string name, string phrase)
        {
            if (OperatingSystem.IsWindows()) Assert.Ignore("such names cannot exist on Windows");
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            temp.Write("pkg/Runtime/" + name, "x");
            temp.Write("pkg/Runtime/" + name + ".meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ac\n");
            CliHarness.AssertOneErrorLine(CliHarness.Run("pack", "--root", root, "--out", temp["out"]), phrase);
            Assert.That(Directory.Exists(temp["out"]) && Directory.GetFiles(temp["out"]).Length > 0, Is.False);
        }

        // 11. A path too long for ustar was "this is a bug" (exit 1).
        [Test]
        public void PackRefusesAPathTooLongForUstarUpFront()
        {
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            string longName = new string('n', 120) + ".cs";
            temp.Write("pkg/Runtime/" + longName, "x");
            temp.Write("pkg/Runtime/" + longName + ".meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ad\n");
            CliHarness.AssertOneErrorLine(CliHarness.Run("pack", "--root", root, "--out", temp["out"]), "too long for a ustar");
        }

        private static string SmallPackage(TempFolder temp, string name, string packageName = "com.example.pack", string version = "1.2.3")
        {
            temp.Write(name + "/package.json", "{ \"name\": \"" + packageName.Replace("\\", "\\\\") + "\", \"version\": \"" + version + "\" }\n");
            temp.Write(name + "/package.json.meta", "fileFormatVersion: 2\nguid: 0000000000000000000000000000000a\n");
            temp.Write(name + "/Runtime.meta", "fileFormatVersion: 2\nguid: 0000000000000000000000000000000b\n");
            temp.Write(name + "/Runtime/Motion.cs", "class Motion {}\n");
            temp.Write(name + "/Runtime/Motion.cs.meta", "fileFormatVersion: 2\nguid: 0000000000000000000000000000000c\n");
            return temp[name];
        }

        // 7. Raw terminal escapes on stdout: check printed model names raw, retarget unmapped joint names,
        // bake/retarget input file names.
        [Test]
        public void StdoutNeverCarriesRawControlCharactersFromFilesOrNames()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string evil = temp.Write("a\u001b]0;pwned\u0007b\r\nforged.bvh", CmuExcerpt(121).Replace("JOINT LHipJoint", "JOINT LHip\u001b[2JJoint"));
            CliRun retarget = CliHarness.Run("retarget", evil, "--to", "model", "--out", temp["r.bvh"], "--model", Model);
            CliHarness.AssertSuccess(retarget);
            Assert.That(retarget.Stdout, Does.Contain("\\x1b]0;pwned\\x07"));

            CliRun bake = CliHarness.Run("bake", evil, "--every", "40", "--out", temp["b.bvh"], "--model", Model, "--method", "slerp");
            CliHarness.AssertSuccess(bake);
            Assert.That(bake.Stdout, Does.Contain("\\x1b"));

            CliRun preview = CliHarness.Run("preview", "--track", "T\u001b[2J=" + evil, "--out", temp["p\u001b]0;x\u0007.html"]);
            CliHarness.AssertSuccess(preview);
            Assert.That(preview.Stdout, Does.Contain("\\x1b]0;x\\x07"));
        }

        // 7 and 17. check printed the metadata's model name raw (ESC]0;… retitles the terminal) and unclipped
        // (20 MB: 13.7 s, 730 MB, 32 MB of stdout).
        [Test]
        public void CheckShowsHostileModelNamesEscapedAndClipped()
        {
            using var temp = new TempFolder();
            string tiny = Path.Combine(TestEnvironment.RepositoryRoot!, "Tests", "Fixtures~", "tiny-model.onnx");
            foreach (string name in new[] { "evil\u001b]0;pwned\u0007\r\nforged", new string('N', 20_000_000) })
            {
                string model = temp["named.onnx"];
                File.WriteAllBytes(model, WithModelName(File.ReadAllBytes(tiny), name));
                var clock = Stopwatch.StartNew();
                CliRun run = CliHarness.Run("check", model);
                Assert.That(run.Stdout.Any(c => c != '\n' && c != '\r' && TerminalText.IsUnsafe(c)), Is.False, "raw control characters on stdout: " + run);
                Assert.That(run.Stdout.Length, Is.LessThan(20_000), run.ToString());
                Assert.That(clock.Elapsed.TotalSeconds, Is.LessThan(10));
                if (name.StartsWith("evil", StringComparison.Ordinal)) Assert.That(run.Stdout, Does.Contain("\\x1b]0;pwned"), run.ToString());
            }
        }

        /// <summary>The ONNX file with the "name" of its deltainterp metadata replaced (top-level protobuf fields copied, field 14 rebuilt).</summary>
        private static byte[] WithModelName(byte[] onnx, string name)
        {
            var output = new MemoryStream();
            int i = 0;
            while (i < onnx.Length)
            {
                int start = i;
                ulong tag = ReadVarint(onnx, ref i);
                int field = (int)(tag >> 3), wire = (int)(tag & 7);
                if (wire == 0)
                {
                    ReadVarint(onnx, ref i);
                }
                else if (wire == 2)
                {
                    int length = (int)ReadVarint(onnx, ref i);
                    int body = i;
                    i += length;
                    if (field == 14)
                    {
                        // StringStringEntryProto: key (1), value (2).
                        int j = body;
                        string key = "", value = "";
                        while (j < body + length)
                        {
                            ulong t = ReadVarint(onnx, ref j);
                            int n = (int)ReadVarint(onnx, ref j);
                            string text = Encoding.UTF8.GetString(onnx, j, n);
                            j += n;
                            if ((t >> 3) == 1) key = text; else value = text;
                        }

                        if (key == "deltainterp")
                        {
                            using var doc = System.Text.Json.JsonDocument.Parse(value);
                            var members = doc.RootElement.EnumerateObject().ToDictionary(p => p.Name, p => (object)p.Value);
                            members["name"] = name;
                            value = System.Text.Json.JsonSerializer.Serialize(members);
                            var entry = new MemoryStream();
                            WriteBytes(entry, 1, Encoding.UTF8.GetBytes(key));
                            WriteBytes(entry, 2, Encoding.UTF8.GetBytes(value));
                            WriteBytes(output, 14, entry.ToArray());
                            continue;
                        }
                    }
                }
                else
                {
                    throw new InvalidDataException($"wire type {wire} at the top level of an ONNX file");
                }

                output.Write(onnx, start, i - start);
            }

            return output.ToArray();
        }

        private static ulong ReadVarint(byte[] bytes, ref int i)
        {
            ulong value = 0;
            for (int shift = 0; ; shift += 7)
            {
                byte b = bytes[i++];
                value |= (ulong)(b & 0x7f) << shift;
                if (b < 0x80) return value;
            }
        }

        private static void WriteBytes(Stream stream, int field, byte[] bytes)
        {
            WriteVarint(stream, (ulong)(field << 3 | 2));
            WriteVarint(stream, (ulong)bytes.Length);
            stream.Write(bytes, 0, bytes.Length);
        }

        private static void WriteVarint(Stream stream, ulong value)
        {
            while (value >= 0x80)
            {
                stream.WriteByte((byte)(value | 0x80));
                value >>= 7;
            }

            stream.WriteByte((byte)value);
        }

        // 9. A command line past ~40 KB aborted ONNX Runtime (exit 134); keys come from a file instead.
        [Test]
        public void LongCommandLinesAreRefusedAndKeysComeFromAFile()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("clip.bvh", CmuExcerpt(481));
            string keys = string.Join(",", Enumerable.Range(0, 8000).Select(k => k.ToString(CultureInfo.InvariantCulture)));
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--keys", keys, "--out", temp["o.bvh"], "--model", Model), "--keys @FILE");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--every", "40", "--out", temp[new string('o', 40_000) + ".bvh"], "--model", Model), "command line");

            string list = temp.Write("keys.txt", "0, 40\n80 120\n160,200,240\n");
            CliRun fromFile = CliHarness.Run("bake", input, "--keys", "@" + list, "--out", temp["k.bvh"], "--model", Model, "--method", "slerp");
            CliHarness.AssertSuccess(fromFile);
            Assert.That(fromFile.Stdout, Does.Contain("7 keys"));
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", input, "--keys", "@" + temp.Path, "--out", temp["d.bvh"], "--model", Model), "is a directory");
        }

        // 11. Exit 1 "this is a bug" instead of exit 2.
        [TestCase("\u00a0")]
        [TestCase("\u2028")]
        public void BlankJointNamesAreBadInput(string name)
        {
            RequireShipped();
            using var temp = new TempFolder();
            string file = temp.Write("blank.bvh", CliHarness.WalkClip(10).Replace("JOINT Spine", "JOINT " + name));
            CliHarness.AssertOneErrorLine(CliHarness.Run("info", file), "blank.bvh:6: ");
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", file, "--out", temp["p.html"]), "blank.bvh:6: ");
            CliHarness.AssertOneErrorLine(CliHarness.Run("bake", file, "--every", "3", "--out", temp["b.bvh"], "--model", Model), "blank.bvh:6: ");
            CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", file, "--to", "model", "--out", temp["r.bvh"], "--model", Model), "blank.bvh:6: ");
        }

        [Test]
        public void PreviewOfAFileWithoutFramesIsBadInput()
        {
            using var temp = new TempFolder();
            string file = temp.Write("zero.bvh", CliHarness.WalkClip(0));
            CliHarness.AssertOneErrorLine(CliHarness.Run("preview", file, "--out", temp["z.html"]), "zero.bvh: has no frames");
            Assert.That(File.Exists(temp["z.html"]), Is.False);
        }

        [Test]
        public void BakePreviewOfMotionWithHugePositionsIsRefusedBeforeAnythingIsWritten()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("huge.bvh", CmuExcerpt(241, 30, "1e200"));
            CliRun run = CliHarness.Run("bake", input, "--every", "40", "--out", temp["o.bvh"], "--preview", temp["o.html"], "--model", Model);
            CliHarness.AssertOneErrorLine(run, "huge.bvh: ");
            Assert.That(File.Exists(temp["o.bvh"]), Is.False);
            Assert.That(File.Exists(temp["o.html"]), Is.False);
        }

        // 12. A 2-frame file with Frame Time: 1e5 ran past 60 s and gigabytes (retarget, bake); 1e6/1e9 threw.
        [TestCase("1e5")]
        [TestCase("1e9")]
        public void AHugeFrameTimeIsRefusedBeforeResampling(string frameTime)
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("slow.bvh", System.Text.RegularExpressions.Regex.Replace(CmuExcerpt(2), "Frame Time: .*", "Frame Time: " + frameTime));
            Assert.That(File.ReadAllText(input), Does.Contain("Frame Time: " + frameTime));
            var clock = Stopwatch.StartNew();
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "retarget", input, "--to", "model", "--out", temp["r.bvh"], "--model", Model), "frames × joints");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(60, "bake", input, "--keys", "0,1", "--out", temp["b.bvh"], "--model", Model), "frames × joints");
            Assert.That(clock.Elapsed.TotalSeconds, Is.LessThan(30));
            Assert.That(TemporaryFiles(temp.Path), Is.Empty);
        }

        // 14. --map on a named pipe hung, on /dev/zero grew to gigabytes; 21. a folder was "no such file".
        [Test]
        public void MapsGoThroughTheSafeInputPath()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("clip.bvh", CmuExcerpt(121));
            string output = temp["o.bvh"];
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", temp.Path, "--model", Model), "is a directory");
            if (!OperatingSystem.IsWindows())
            {
                string fifo = CliHarness.MakeFifo(temp["map.json"]);
                CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", fifo, "--model", Model), "named pipe");
                CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", "/dev/zero", "--model", Model), "device");
            }

            string huge = temp.Write("huge.json", "{" + string.Concat(Enumerable.Range(0, 200_000).Select(i => $"\"junk{i}\": \"x\",")) + "\"Hips\": \"Hips\"}");
            CliHarness.AssertOneErrorLine(CliHarness.RunWithin(30, "retarget", input, "--to", "model", "--out", output, "--map", huge, "--model", Model), "at most");
            Assert.That(File.Exists(output), Is.False);

            // 11: a blank key (or one of blank characters) is bad input naming the map.
            foreach (string key in new[] { "", " ", "\u00a0", "\u2028" })
            {
                string blank = temp.Write("blank.json", "{\"" + key + "\": \"Hips\"}");
                CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", input, "--to", "model", "--out", output, "--map", blank, "--model", Model), "blank.json:1: ");
            }

            // 21 for check: a folder is a folder.
            CliHarness.AssertOneErrorLine(CliHarness.Run("check", temp.Path), "is a directory");
        }

        // 19. A degenerate reference pose was reported under the map's name ("lafan1: …"), not the file.
        [Test]
        public void ADegenerateReferencePoseNamesTheFile()
        {
            RequireShipped();
            using var temp = new TempFolder();
            // Every offset zero: no leg length.
            string text = CmuExcerpt(10);
            string[] lines = text.Split('\n');
            for (int i = 0; i < lines.Length; i++)
            {
                if (lines[i].TrimStart().StartsWith("OFFSET", StringComparison.Ordinal)) lines[i] = "OFFSET 0 0 0";
            }

            string flat = temp.Write("flat.bvh", string.Join("\n", lines));
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", flat, "--to", "model", "--out", temp["o.bvh"], "--model", Model));
            Assert.That(line, Does.StartWith(flat + ": "), line);
        }

        // 20. Option errors printed System.Nullable`1[System.Int32].
        [Test]
        public void OptionErrorsSayTypesInWords()
        {
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("bake", "x.bvh", "--every", "abc", "--out", "o.bvh"), "a whole number");
            Assert.That(line, Does.Not.Contain("System."));
            line = CliHarness.AssertOneErrorLine(CliHarness.Run("retarget", "x.bvh", "--to", "model", "--out", "o.bvh", "--scale", "big"), "a number");
            Assert.That(line, Does.Not.Contain("System."));
        }

        // 24. Unknown target joints in a --map were ignored without a word.
        [Test]
        public void UnknownTargetJointsInAMapAreNamedInAWarning()
        {
            RequireShipped();
            using var temp = new TempFolder();
            string input = temp.Write("clip.bvh", CmuExcerpt(121));
            string map = temp.Write("map.json", "{\"Hipz\": \"Hips\", \"Tail\u001b[2J\": \"LowerBack\"}");
            CliRun run = CliHarness.Run("retarget", input, "--to", "model", "--out", temp["o.bvh"], "--map", map, "--model", Model);
            CliHarness.AssertSuccess(run);
            Assert.That(run.Stdout, Does.Contain("warning:"));
            Assert.That(run.Stdout, Does.Contain("Hipz"));
            Assert.That(run.Stdout, Does.Contain("Tail\\x1b[2J"));
        }

        // 13. A model's training.fps of 1e6 passed check; retarget --model then resampled into millions of frames.
        [TestCase("1000000")]
        [TestCase("1e12")]
        [TestCase("0.001")]
        public void TheContractBoundsTheTrainingFrameRate(string fps)
        {
            var report = new Core.Inference.ModelCheckReport();
            string metadata = Tests.Inference.ModelContractTests.MetadataJson().Replace("\"fps\": 30", "\"fps\": " + fps);
            Assert.That(metadata, Does.Contain("\"fps\": " + fps));
            Core.Inference.ModelContract.Parse(metadata, "fast.onnx", report);
            Assert.That(report.HasErrors, Is.True, string.Join("\n", report.Select(c => c.Message)));
            Assert.That(report.Any(c => c.Message.Contains("training.fps")), Is.True);

            var fine = new Core.Inference.ModelCheckReport();
            Core.Inference.ModelContract.Parse(Tests.Inference.ModelContractTests.MetadataJson(), "ok.onnx", fine);
            Assert.That(fine.HasErrors, Is.False);
        }

        // 18. SIGTERM during a write left .NAME.XXXXXXXX.tmp files behind (25 MB seen from pack): the real
        // tool in its own process, terminated while it writes its first archive.
        [Test]
        public void SigtermDuringPackRemovesTheTemporaryFile()
        {
            if (OperatingSystem.IsWindows()) Assert.Ignore("POSIX signals");
            using var temp = new TempFolder();
            string root = SmallPackage(temp, "pkg");
            var random = new Random(16);
            var bytes = new byte[24 << 20];
            random.NextBytes(bytes);
            File.WriteAllBytes(Path.Combine(root, "Runtime", "Big.bin"), bytes);
            temp.Write("pkg/Runtime/Big.bin.meta", "fileFormatVersion: 2\nguid: 000000000000000000000000000000ae\n");
            string outDir = temp["out"];
            var start = new ProcessStartInfo("dotnet") { UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true };
            foreach (string a in new[] { typeof(Program).Assembly.Location, "pack", "--root", root, "--out", outDir }) start.ArgumentList.Add(a);
            using Process tool = Process.Start(start)!;
            tool.StandardOutput.ReadToEndAsync();
            tool.StandardError.ReadToEndAsync();
            var clock = Stopwatch.StartNew();
            while (!tool.HasExited && clock.Elapsed.TotalSeconds < 60 && (!Directory.Exists(outDir) || TemporaryFiles(outDir).Length == 0)) System.Threading.Thread.Sleep(5);
            if (tool.HasExited) Assert.Inconclusive("pack finished before it could be interrupted");
            Assert.That(TemporaryFiles(outDir), Is.Not.Empty, "the write is under way");
            using (Process kill = Process.Start("kill", new[] { "-TERM", tool.Id.ToString(CultureInfo.InvariantCulture) })!) kill.WaitForExit();
            Assert.That(tool.WaitForExit(60_000), Is.True);
            Assert.That(tool.ExitCode, Is.EqualTo(143), "ended by SIGTERM");
            Assert.That(TemporaryFiles(outDir), Is.Empty, "no temporary file left");
        }

        // 18. SIGTERM during a write left .NAME.XXXXXXXX.tmp files behind.
        [Test]
        public void AnInterruptedWriteLeavesNoTemporaryFile()
        {
            using var temp = new TempFolder();
            string path = temp.Write("out.bin", "old");
            var started = new System.Threading.ManualResetEventSlim();
            var release = new System.Threading.ManualResetEventSlim();
            var writer = System.Threading.Tasks.Task.Run(() =>
            {
                try
                {
                    OutputFile.Write(path, s =>
                    {
                        s.Write(new byte[1000], 0, 1000);
                        started.Set();
                        release.Wait();
                        throw new IOException("simulated end of the process");
                    });
                }
                catch (IOException)
                {
                }
            });
            Assert.That(started.Wait(TimeSpan.FromSeconds(30)), Is.True);
            Assert.That(TemporaryFiles(temp.Path), Has.Length.EqualTo(1), "the write is under way");
            OutputFile.DeleteTemporaries(); // what the SIGINT/SIGTERM handler does
            Assert.That(TemporaryFiles(temp.Path), Is.Empty);
            release.Set();
            writer.Wait();
            Assert.That(File.ReadAllText(path), Is.EqualTo("old"));
        }
    }
}
