using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using DeltaInterpolator.Core.IO;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// Reads BVH motion capture files: any channel order, 3 or 6 channels on any joint, End Sites,
    /// LF, CRLF or CR line endings, tabs, exponents, any nesting depth. Euler angles are composed in the
    /// order of each joint's CHANNELS line, intrinsic, degrees (as BVH and the official LaFAN1 code do).
    /// Quaternion signs are left as the Euler conversion gives them; apply
    /// <see cref="Quaternions.FixContinuity"/> when a continuous sign is needed.
    /// </summary>
    /// <remarks>
    /// Every malformed input throws <see cref="BvhFormatException"/> naming the file, the line and what
    /// was expected — never an index, format or null-reference error. The parts are reusable by other
    /// importers: <see cref="BvhLineReader"/> (lines), <see cref="BvhTokenizer"/> (words of the
    /// hierarchy), <see cref="BvhHierarchyParser"/> (the joint grammar, without recursion),
    /// <see cref="BvhNumberParser"/> (finite decimals from bytes) and <see cref="BvhChannelPlan"/>
    /// (motion columns to positions and quaternions). The motion section is parsed straight from the
    /// bytes, without a string per value.
    /// </remarks>
    public static class BvhReader
    {
        /// <summary>Reads the BVH file at <paramref name="path"/>.</summary>
        /// <exception cref="BvhFormatException">The file is not valid BVH; the message says where and why.</exception>
        /// <exception cref="InputPathException">The path is missing, a directory, a named pipe or another non-regular file.</exception>
        /// <exception cref="System.IO.IOException">The file cannot be read.</exception>
        public static BvhAnimation Read(string path)
        {
            byte[] data = InputFile.ReadAllBytes(path, "a .bvh file");
            return Parse(data, path);
        }

        /// <summary>Parses BVH text; <paramref name="sourceName"/> names it in error messages.</summary>
        /// <exception cref="BvhFormatException">The text is not valid BVH.</exception>
        public static BvhAnimation Parse(string text, string sourceName)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            return Parse(Encoding.UTF8.GetBytes(text), sourceName);
        }

        /// <summary>Parses BVH bytes (ASCII or UTF-8); <paramref name="sourceName"/> names them in error messages.</summary>
        /// <exception cref="BvhFormatException">The data is not valid BVH.</exception>
        public static BvhAnimation Parse(byte[] data, string sourceName)
        {
            if (data == null) throw new ArgumentNullException(nameof(data));
            string source = sourceName ?? "<bvh>";
            var lines = new BvhLineReader(data);
            var tokens = new BvhTokenizer(lines);
            List<BvhJointDefinition> joints = new BvhHierarchyParser(tokens, source).Parse();
            var motion = new MotionSection(tokens, source);
            return motion.Read(joints);
        }

        /// <summary>The MOTION section: Frames:, Frame Time: and one line of values per frame.</summary>
        private sealed class MotionSection
        {
            private readonly BvhTokenizer _tokens;
            private readonly BvhLineReader _lines;
            private readonly string _source;

            public MotionSection(BvhTokenizer tokens, string source)
            {
                _tokens = tokens;
                _lines = tokens.Lines;
                _source = source;
            }

            public BvhAnimation Read(List<BvhJointDefinition> joints)
            {
                int frameCount = ParseFrameCount();
                double frameTime = ParseFrameTime();
                if (_tokens.HasMoreOnLine)
                {
                    throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(_tokens.RestOfLineFirst)}'", "expected nothing after the frame time on the Frame Time: line");
                }

                int jointCount = joints.Count;
                var names = new string[jointCount];
                var parents = new int[jointCount];
                var offsets = new double[jointCount * 3];
                var channelLists = new BvhChannel[jointCount][];
                var endSites = new Vector3D[jointCount][];
                for (int j = 0; j < jointCount; j++)
                {
                    BvhJointDefinition b = joints[j];
                    names[j] = b.Name;
                    parents[j] = b.Parent;
                    offsets[3 * j] = b.Offset.X;
                    offsets[3 * j + 1] = b.Offset.Y;
                    offsets[3 * j + 2] = b.Offset.Z;
                    channelLists[j] = b.Channels!;
                    endSites[j] = b.EndSites.ToArray();
                }

                var skeleton = new Skeleton(names, parents, offsets);
                var plan = new BvhChannelPlan(channelLists, offsets);
                int channelCount = plan.ChannelCount;

                long positionsLength = (long)frameCount * jointCount * 3;
                if (positionsLength * 4 / 3 > int.MaxValue)
                {
                    throw Error(_lines.LineNumber, $"Frames: {frameCount} is too many for {jointCount} joints", "expected fewer frames (split the file)");
                }

                // Never trust the declared count for allocation beyond what the file can hold: each
                // value takes at least two bytes ("0 "), so a huge Frames: on a short file fails below
                // with a clear message instead of allocating gigabytes first.
                long maxFrames = channelCount == 0 ? 0 : _lines.RemainingBytes / (2L * channelCount) + 1;
                int allocFrames = (int)Math.Min(frameCount, maxFrames);
                var positions = new double[allocFrames * jointCount * 3];
                var rotations = new double[allocFrames * jointCount * 4];
                var row = new double[channelCount];

                for (int f = 0; f < frameCount; f++)
                {
                    if (!_lines.NextDataLine(out int start, out int end))
                    {
                        throw Error(Math.Max(_lines.LineNumber, 1), $"the file ends after {f} of the {frameCount} frames that Frames: declares (truncated file?)", $"expected {frameCount} motion lines of {channelCount} values");
                    }

                    if (f >= allocFrames)
                    {
                        // Unreachable for well-formed input; guards the allocation bound above.
                        throw Error(_lines.LineNumber, $"frame {f} does not fit the file size", $"expected {channelCount} values per motion line");
                    }

                    ParseRow(start, end, row, f, frameCount);
                    plan.ApplyRow(row, f, positions, rotations);
                }

                if (_lines.NextDataLine(out _, out _))
                {
                    throw Error(_lines.LineNumber, $"more motion lines than the {frameCount} that Frames: declares", $"expected exactly {frameCount} motion lines (fix the Frames: count)");
                }

                var motion = new MotionClip(skeleton, frameCount, frameTime, positions, rotations);
                return new BvhAnimation(motion, channelLists, endSites, _source);
            }

            private int ParseFrameCount()
            {
                string frames = _tokens.Next(_source, "expected 'Frames: N' after MOTION");
                int line = _tokens.TokenLine;
                if (frames != "Frames:")
                {
                    throw Error(line, $"found '{BvhTokenizer.Shorten(frames)}' after MOTION", "expected 'Frames: N'");
                }

                if (!_tokens.TryPeek(out string countText) || _tokens.TokenLine != line)
                {
                    throw Error(line, "Frames: has no value", "expected 'Frames: N' with a whole number N");
                }

                _tokens.Skip();
                if (!int.TryParse(countText, NumberStyles.None, CultureInfo.InvariantCulture, out int count))
                {
                    throw Error(line, $"Frames: '{BvhTokenizer.Shorten(countText)}'", "expected a whole number of frames");
                }

                if (_tokens.HasMoreOnLine)
                {
                    throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(_tokens.RestOfLineFirst)}'", "expected nothing after the frame count on the Frames: line");
                }

                return count;
            }

            private double ParseFrameTime()
            {
                string frame = _tokens.Next(_source, "expected 'Frame Time: seconds' after the Frames: line");
                int line = _tokens.TokenLine;
                string time = frame == "Frame" && _tokens.TryPeek(out string t) && _tokens.TokenLine == line ? t : "";
                if (frame != "Frame" || time != "Time:")
                {
                    throw Error(line, $"found '{BvhTokenizer.Shorten(frame)}' after the Frames: line", "expected 'Frame Time: seconds'");
                }

                _tokens.Skip();
                const string expected = "expected the seconds per frame, e.g. 'Frame Time: 0.033333'";
                if (!_tokens.TryPeek(out string token) || _tokens.TokenLine != line)
                {
                    throw Error(line, "Frame Time: has too few values", expected);
                }

                _tokens.Skip();
                if (!BvhNumberParser.TryParseText(token, out double value, out string? problem))
                {
                    throw Error(line, $"Frame Time:: {problem}", expected);
                }

                if (!(value > 0))
                {
                    throw Error(line, $"Frame Time: {value.ToString(CultureInfo.InvariantCulture)}", "expected a positive number of seconds per frame");
                }

                return value;
            }

            private void ParseRow(int start, int end, double[] row, int frame, int frameCount)
            {
                int count = 0;
                int i = start;
                byte[] d = _lines.Data;
                while (true)
                {
                    while (i < end && (d[i] == (byte)' ' || d[i] == (byte)'\t')) i++;
                    if (i >= end) break;
                    int tokenStart = i;
                    while (i < end && d[i] != (byte)' ' && d[i] != (byte)'\t') i++;
                    if (count >= row.Length)
                    {
                        int total = count;
                        int k = tokenStart;
                        while (k < end)
                        {
                            while (k < end && (d[k] == (byte)' ' || d[k] == (byte)'\t')) k++;
                            if (k >= end) break;
                            total++;
                            while (k < end && d[k] != (byte)' ' && d[k] != (byte)'\t') k++;
                        }

                        throw Error(_lines.LineNumber, $"frame {frame + 1} of {frameCount} has {total} values", $"expected {row.Length}, one per channel declared in the hierarchy");
                    }

                    if (!BvhNumberParser.TryParse(d, tokenStart, i, out double value))
                    {
                        string token = Encoding.UTF8.GetString(d, tokenStart, i - tokenStart);
                        BvhNumberParser.TryParseText(token, out _, out string? problem);
                        throw Error(_lines.LineNumber, $"frame {frame + 1}, value {count + 1}: {problem}", "expected a finite decimal number such as -12.5 or 1.2e-3");
                    }

                    row[count++] = value;
                }

                if (count != row.Length)
                {
                    throw Error(_lines.LineNumber, $"frame {frame + 1} of {frameCount} has {count} values", $"expected {row.Length}, one per channel declared in the hierarchy");
                }
            }

            private BvhFormatException Error(int line, string problem, string expected) => new BvhFormatException(_source, line, problem, expected);
        }
    }
}
