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

namespace DeltaInterpolator.Tests.Cli
{
    /// <summary>Files and models the tool's refusal tests share: LaFAN1-shaped data folders, the shipped model and
    /// demo clip (and excerpts of it), temporary files left in a folder.</summary>
    internal static class CliTestFiles
    {
        /// <summary>A LaFAN1-shaped data folder of synthetic walking clips: subject 5 for testing, subject 1 for statistics.</summary>
        internal static string DataFolder(TempFolder temp, string name, string test, string? training = null)
        {
            temp.Write(name + "/walk_subject5.bvh", test);
            temp.Write(name + "/walk_subject1.bvh", training ?? CliHarness.WalkClip(130));
            return temp[name];
        }

        internal static string Model => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "LaFAN1Model", "DeltaInterpolator-LaFAN1.onnx");

        internal static string CmuClip => Path.Combine(TestEnvironment.RepositoryRoot!, "Samples~", "Demo", "cmu_01_01_jumps_turn.bvh");

        internal static void RequireShipped()
        {
            if (TestEnvironment.RepositoryRoot == null || !File.Exists(Model) || !File.Exists(CmuClip))
            {
                Assert.Ignore("the shipped model or the demo clip is absent; skipping");
            }
        }

        /// <summary>The demo clip's first <paramref name="frames"/> frames, with one root value replaced at <paramref name="frame"/>.</summary>
        internal static string CmuExcerpt(int frames, int frame = -1, string value = "")
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

        internal static string[] TemporaryFiles(string folder) => Directory.GetFiles(folder, "*.tmp", SearchOption.AllDirectories);
    }

    /// <summary>A stream that fails like a full disk after a number of bytes.</summary>
    internal sealed class StreamThatFills : Stream
    {
        private readonly Stream _inner;
        private long _left;

        public StreamThatFills(Stream inner, long bytes)
        {
            _inner = inner;
            _left = bytes;
        }

        public override bool CanRead => false;
        public override bool CanSeek => false;
        public override bool CanWrite => true;
        public override long Length => _inner.Length;
        public override long Position { get => _inner.Position; set => throw new NotSupportedException(); }
        public override void Flush() => _inner.Flush();
        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();

        public override void Write(byte[] buffer, int offset, int count)
        {
            int now = (int)Math.Min(count, _left);
            _inner.Write(buffer, offset, now);
            _left -= now;
            if (now < count) throw new IOException("No space left on device (simulated)");
        }

        public override void Write(ReadOnlySpan<byte> buffer)
        {
            byte[] copy = buffer.ToArray();
            Write(copy, 0, copy.Length);
        }
    }
}
