using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using DeltaInterpolator.Cli;
using DeltaInterpolator.Core.IO;
using NUnit.Framework;
using static DeltaInterpolator.Tests.Cli.CliTestFiles;

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>
    /// What reaches the terminal (issues 8, 16): control characters from files, joint and model names are escaped
    /// and long names clipped, on stdout and stderr alike. Each case broke before its fix.
    /// </summary>
    [NonParallelizable]
    public class TerminalOutputEscapingTests
    {
        // 10. Escape sequences and control bytes from a file reached the terminal raw.
        [Test]
        public void ControlCharactersFromFilesAreEscapedAndLongNamesClipped()
        {
            using var temp = new TempFolder();
            string named = temp.Write("esc.bvh", CliHarness.WalkClip(3).Replace("JOINT Spine", "JOINT Sp\u001b[2Jine\u0007\u202e"));
            CliRun info = CliHarness.Run("info", named);
            CliHarness.AssertSuccess(info);
            // The table may wrap the name; each escape must be there and no raw control character.
            Assert.That(info.Stdout, Does.Contain("Sp\\x1b["));
            Assert.That(info.Stdout, Does.Contain("\\x07"));
            Assert.That(info.Stdout, Does.Contain("\\u202e"));

            string badNumber = temp.Write("escbad.bvh", CliHarness.WalkClip(3).Replace("OFFSET 0 10 0", "OFFSET 0 \u001b]0;title\u0007 0"));
            Assert.That(CliHarness.AssertOneErrorLine(CliHarness.Run("info", badNumber)), Does.Contain("\\x1b]0;title\\x07"));

            string twice = temp.Write("twice.bvh", CliHarness.WalkClip(3).Replace("ROOT Hips", "ROOT " + new string('N', 10_000_000)).Replace("JOINT Spine", "JOINT " + new string('N', 10_000_000)));
            string line = CliHarness.AssertOneErrorLine(CliHarness.Run("info", twice), "is used twice");
            Assert.That(line.Length, Is.LessThan(300), "a 10 MB name makes a short message");

            string escPath = temp.Write("a\u001b[2Jb/x.bvh", "not bvh");
            Assert.That(CliHarness.AssertOneErrorLine(CliHarness.Run("info", escPath)), Does.Contain("a\\x1b[2Jb"));
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
    }
}
