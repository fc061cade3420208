using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// Reads BVH motion capture files: any channel order, 3 or 6 channels on any joint, End Sites,
    /// CRLF or LF line endings, tabs, exponents. Euler angles are composed in the order of each joint's
    /// CHANNELS line, intrinsic, degrees (as BVH and the official LaFAN1 code do). Quaternion signs are
    /// left as the Euler conversion gives them; apply <see cref="Quaternions.FixContinuity"/> when a
    /// continuous sign is needed.
    /// </summary>
    /// <remarks>
    /// Every malformed input throws <see cref="BvhFormatException"/> naming the file, the line and what
    /// was expected — never an index, format or null-reference error. The motion section is parsed
    /// straight from the bytes, without a string per value, with an exact fast path for short decimals
    /// (the form every exporter writes; the same double that <c>double.Parse</c> gives).
    /// </remarks>
    public static class BvhReader
    {
        private const string ChannelNames = "Xposition, Yposition, Zposition, Xrotation, Yrotation or Zrotation";
        private const double DegreesToRadians = Math.PI / 180.0;

        private static readonly double[] PowersOfTen =
        {
            1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
            1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
        };

        /// <summary>Reads the BVH file at <paramref name="path"/>.</summary>
        /// <exception cref="BvhFormatException">The file is not valid BVH; the message says where and why.</exception>
        /// <exception cref="IOException">The file cannot be read (e.g. <see cref="FileNotFoundException"/>).</exception>
        public static BvhAnimation Read(string path)
        {
            byte[] data = File.ReadAllBytes(path);
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
            var parser = new Parser(data, sourceName ?? "<bvh>");
            return parser.Run();
        }

        private sealed class JointBuilder
        {
            public string Name = "";
            public int Parent;
            public int Line;
            public Vector3D Offset;
            public bool HasOffset;
            public BvhChannel[]? Channels;
            public readonly List<Vector3D> EndSites = new List<Vector3D>();
        }

        private sealed class Parser
        {
            private readonly byte[] _data;
            private readonly string _source;
            private int _pos;
            private int _lineNumber;
            private readonly List<string> _tokens = new List<string>();
            private int _tokenIndex;
            private int _tokenLine;
            private readonly List<JointBuilder> _joints = new List<JointBuilder>();
            private readonly Dictionary<string, int> _jointLines = new Dictionary<string, int>(StringComparer.Ordinal);

            public Parser(byte[] data, string source)
            {
                _data = data;
                _source = source;
                // A UTF-8 byte order mark is not part of the text.
                if (data.Length >= 3 && data[0] == 0xEF && data[1] == 0xBB && data[2] == 0xBF) _pos = 3;
            }

            public BvhAnimation Run()
            {
                if (!TryPeekToken(out string first))
                {
                    throw Error(1, "the file is empty", "expected a BVH file starting with HIERARCHY");
                }

                if (first != "HIERARCHY")
                {
                    throw Error(_tokenLine, $"found '{Shorten(first)}' where the file should start", "expected HIERARCHY (is this a BVH file?)");
                }

                NextToken();
                string root = ExpectToken("expected ROOT and the root joint's name after HIERARCHY");
                if (root != "ROOT")
                {
                    throw Error(_tokenLine, $"found '{Shorten(root)}' after HIERARCHY", "expected ROOT and the root joint's name");
                }

                ParseJoint(-1, _tokenLine);

                if (!TryPeekToken(out string afterRoot))
                {
                    throw Error(_lineNumber, "the file ends after the hierarchy", "expected a MOTION section with Frames: and Frame Time:");
                }

                if (afterRoot == "ROOT")
                {
                    throw Error(_tokenLine, "a second ROOT", "expected MOTION after the first skeleton (one skeleton per file)");
                }

                if (afterRoot == "}")
                {
                    throw Error(_tokenLine, "a '}' without a matching '{' (unbalanced braces)", "expected MOTION after the root joint's closing brace");
                }

                if (afterRoot != "MOTION")
                {
                    throw Error(_tokenLine, $"found '{Shorten(afterRoot)}' after the hierarchy", "expected MOTION");
                }

                NextToken();
                int frameCount = ParseFrameCount();
                double frameTime = ParseFrameTime();
                RequireEndOfLine("expected nothing after the frame time on the Frame Time: line");

                return BuildAnimation(frameCount, frameTime);
            }

            private void ParseJoint(int parent, int line)
            {
                string name = RestOfLineAsName(parent < 0 ? "ROOT" : "JOINT");
                if (_jointLines.TryGetValue(name, out int firstLine))
                {
                    throw Error(line, $"joint name '{name}' is used twice (first on line {firstLine})", "expected unique joint names");
                }

                _jointLines.Add(name, line);
                var joint = new JointBuilder { Name = name, Parent = parent, Line = line };
                int index = _joints.Count;
                _joints.Add(joint);

                ExpectOpeningBrace($"joint '{name}'");
                while (true)
                {
                    if (!TryNextToken(out string token))
                    {
                        throw Error(_lineNumber, $"the file ends inside joint '{name}' (unbalanced braces or truncated file)", "expected '}' closing the joint, then MOTION");
                    }

                    int tokenLine = _tokenLine;
                    switch (token)
                    {
                        case "OFFSET":
                            if (joint.HasOffset) throw Error(tokenLine, $"a second OFFSET in joint '{name}'", "expected one OFFSET per joint");
                            joint.Offset = ParseOffset($"joint '{name}'");
                            joint.HasOffset = true;
                            break;
                        case "CHANNELS":
                            if (joint.Channels != null) throw Error(tokenLine, $"a second CHANNELS line in joint '{name}'", "expected one CHANNELS line per joint");
                            joint.Channels = ParseChannels(name);
                            break;
                        case "JOINT":
                            RequireOffsetAndChannels(joint, tokenLine);
                            ParseJoint(index, tokenLine);
                            break;
                        case "End":
                            RequireOffsetAndChannels(joint, tokenLine);
                            ParseEndSite(joint, tokenLine);
                            break;
                        case "}":
                            RequireOffsetAndChannels(joint, tokenLine);
                            return;
                        case "MOTION":
                            throw Error(tokenLine, $"MOTION while joint '{name}' is still open (unbalanced braces)", "expected '}' closing every joint before MOTION");
                        case "ROOT":
                            throw Error(tokenLine, $"ROOT inside joint '{name}'", "expected JOINT, End Site or '}'");
                        default:
                            throw Error(tokenLine, $"found '{Shorten(token)}' in joint '{name}'", "expected OFFSET, CHANNELS, JOINT, End Site or '}'");
                    }
                }
            }

            private void RequireOffsetAndChannels(JointBuilder joint, int line)
            {
                if (!joint.HasOffset)
                {
                    throw Error(line, $"joint '{joint.Name}' has no OFFSET", "expected OFFSET x y z before its children or closing brace");
                }

                if (joint.Channels == null)
                {
                    throw Error(line, $"joint '{joint.Name}' has no CHANNELS line", "expected CHANNELS 3 or CHANNELS 6 with the channel names before its children or closing brace");
                }
            }

            private void ParseEndSite(JointBuilder joint, int line)
            {
                string site = ExpectToken("expected 'Site' after 'End'");
                if (site != "Site")
                {
                    throw Error(_tokenLine, $"found 'End {Shorten(site)}' in joint '{joint.Name}'", "expected 'End Site'");
                }

                ExpectOpeningBrace($"the End Site of joint '{joint.Name}'");
                string offset = ExpectToken($"expected OFFSET in the End Site of joint '{joint.Name}'");
                if (offset != "OFFSET")
                {
                    throw Error(_tokenLine, $"found '{Shorten(offset)}' in the End Site of joint '{joint.Name}'", "expected OFFSET x y z");
                }

                joint.EndSites.Add(ParseOffset($"the End Site of joint '{joint.Name}'"));
                string close = ExpectToken($"expected '}}' closing the End Site of joint '{joint.Name}' (unbalanced braces)");
                if (close != "}")
                {
                    throw Error(_tokenLine, $"found '{Shorten(close)}' in the End Site of joint '{joint.Name}'", "expected '}' closing the End Site (an End Site holds only an OFFSET)");
                }
            }

            private void ExpectOpeningBrace(string what)
            {
                string brace = ExpectToken($"expected '{{' opening {what}");
                if (brace != "{")
                {
                    throw Error(_tokenLine, $"found '{Shorten(brace)}' after the name of {what}", "expected '{'");
                }
            }

            private Vector3D ParseOffset(string what)
            {
                int line = _tokenLine;
                double x = ParseHierarchyNumber(line, $"the OFFSET of {what}", "expected three numbers: OFFSET x y z");
                double y = ParseHierarchyNumber(line, $"the OFFSET of {what}", "expected three numbers: OFFSET x y z");
                double z = ParseHierarchyNumber(line, $"the OFFSET of {what}", "expected three numbers: OFFSET x y z");
                return new Vector3D(x, y, z);
            }

            private double ParseHierarchyNumber(int line, string what, string expected)
            {
                if (!TryPeekToken(out string token) || _tokenLine != line)
                {
                    throw Error(line, $"{what} has too few values", expected);
                }

                NextToken();
                if (!TryParseNumberText(token, out double value, out string? problem))
                {
                    throw Error(line, $"{what}: {problem}", expected);
                }

                return value;
            }

            private BvhChannel[] ParseChannels(string joint)
            {
                int line = _tokenLine;
                if (!TryPeekToken(out string countText) || _tokenLine != line)
                {
                    throw Error(line, $"CHANNELS of joint '{joint}' has no channel count", "expected CHANNELS 3 or CHANNELS 6 followed by the channel names");
                }

                NextToken();
                if (!int.TryParse(countText, NumberStyles.None, CultureInfo.InvariantCulture, out int count) || (count != 3 && count != 6))
                {
                    throw Error(line, $"CHANNELS {Shorten(countText)} on joint '{joint}'", "expected 3 or 6 channels");
                }

                var channels = new BvhChannel[count];
                for (int i = 0; i < count; i++)
                {
                    if (!TryPeekToken(out string name) || _tokenLine != line)
                    {
                        throw Error(line, $"CHANNELS {count} of joint '{joint}' names only {i} channels", $"expected {count} channel names on the CHANNELS line");
                    }

                    NextToken();
                    if (!BvhChannels.TryParse(name, out channels[i]))
                    {
                        throw Error(line, $"unknown channel '{Shorten(name)}' on joint '{joint}'", "expected " + ChannelNames);
                    }
                }

                if (TryPeekToken(out string extra) && _tokenLine == line)
                {
                    throw Error(line, $"CHANNELS {count} of joint '{joint}' is followed by '{Shorten(extra)}'", $"expected exactly {count} channel names");
                }

                string? problem = BvhAnimation.DescribeChannelProblem(channels);
                if (problem != null)
                {
                    throw Error(line, $"joint '{joint}': {problem}", "expected 3 rotation channels, 3 position channels, or all 6, each once");
                }

                return channels;
            }

            private int ParseFrameCount()
            {
                string frames = ExpectToken("expected 'Frames: N' after MOTION");
                int line = _tokenLine;
                if (frames != "Frames:")
                {
                    throw Error(line, $"found '{Shorten(frames)}' after MOTION", "expected 'Frames: N'");
                }

                if (!TryPeekToken(out string countText) || _tokenLine != line)
                {
                    throw Error(line, "Frames: has no value", "expected 'Frames: N' with a whole number N");
                }

                NextToken();
                if (!int.TryParse(countText, NumberStyles.None, CultureInfo.InvariantCulture, out int count))
                {
                    throw Error(line, $"Frames: '{Shorten(countText)}'", "expected a whole number of frames");
                }

                RequireEndOfLine("expected nothing after the frame count on the Frames: line");
                return count;
            }

            private double ParseFrameTime()
            {
                string frame = ExpectToken("expected 'Frame Time: seconds' after the Frames: line");
                int line = _tokenLine;
                string time = frame == "Frame" && TryPeekToken(out string t) && _tokenLine == line ? t : "";
                if (frame != "Frame" || time != "Time:")
                {
                    throw Error(line, $"found '{Shorten(frame)}' after the Frames: line", "expected 'Frame Time: seconds'");
                }

                NextToken();
                double value = ParseHierarchyNumber(line, "Frame Time:", "expected the seconds per frame, e.g. 'Frame Time: 0.033333'");
                if (!(value > 0))
                {
                    throw Error(line, $"Frame Time: {value.ToString(CultureInfo.InvariantCulture)}", "expected a positive number of seconds per frame");
                }

                return value;
            }

            private BvhAnimation BuildAnimation(int frameCount, double frameTime)
            {
                int jointCount = _joints.Count;
                var names = new string[jointCount];
                var parents = new int[jointCount];
                var offsets = new double[jointCount * 3];
                var channelLists = new BvhChannel[jointCount][];
                var endSites = new Vector3D[jointCount][];
                int channelCount = 0;
                for (int j = 0; j < jointCount; j++)
                {
                    JointBuilder b = _joints[j];
                    names[j] = b.Name;
                    parents[j] = b.Parent;
                    offsets[3 * j] = b.Offset.X;
                    offsets[3 * j + 1] = b.Offset.Y;
                    offsets[3 * j + 2] = b.Offset.Z;
                    channelLists[j] = b.Channels!;
                    endSites[j] = b.EndSites.ToArray();
                    channelCount += b.Channels!.Length;
                }

                var skeleton = new Skeleton(names, parents, offsets);

                // Column plan: for each joint, where its position and rotation values sit on a line.
                var positionColumns = new int[jointCount * 3];
                var rotationColumns = new int[jointCount * 3];
                var orders = new EulerOrder[jointCount];
                var hasPosition = new bool[jointCount];
                var hasRotation = new bool[jointCount];
                int column = 0;
                for (int j = 0; j < jointCount; j++)
                {
                    Span<int> axes = stackalloc int[3];
                    int r = 0;
                    foreach (BvhChannel c in channelLists[j])
                    {
                        if (c.IsRotation())
                        {
                            rotationColumns[3 * j + r] = column;
                            axes[r++] = c.Axis();
                            hasRotation[j] = true;
                        }
                        else
                        {
                            positionColumns[3 * j + c.Axis()] = column;
                            hasPosition[j] = true;
                        }

                        column++;
                    }

                    orders[j] = r == 3 ? EulerOrders.FromAxes(axes[0], axes[1], axes[2]) : EulerOrder.Xyz;
                }

                long positionsLength = (long)frameCount * jointCount * 3;
                if (positionsLength * 4 / 3 > int.MaxValue)
                {
                    throw Error(_lineNumber, $"Frames: {frameCount} is too many for {jointCount} joints", "expected fewer frames (split the file)");
                }

                // Never trust the declared count for allocation beyond what the file can hold: each
                // value takes at least two bytes ("0 "), so a huge Frames: on a short file fails below
                // with a clear message instead of allocating gigabytes first.
                long maxFrames = channelCount == 0 ? 0 : (_data.Length - _pos) / (2L * channelCount) + 1;
                int allocFrames = (int)Math.Min(frameCount, maxFrames);
                var positions = new double[allocFrames * jointCount * 3];
                var rotations = new double[allocFrames * jointCount * 4];
                var row = new double[channelCount];

                int f = 0;
                while (f < frameCount)
                {
                    if (!NextDataLine(out int start, out int end))
                    {
                        throw Error(Math.Max(_lineNumber, 1), $"the file ends after {f} of the {frameCount} frames that Frames: declares (truncated file?)", $"expected {frameCount} motion lines of {channelCount} values");
                    }

                    if (f >= allocFrames)
                    {
                        // Unreachable for well-formed input; guards the allocation bound above.
                        throw Error(_lineNumber, $"frame {f} does not fit the file size", $"expected {channelCount} values per motion line");
                    }

                    ParseRow(start, end, row, f, frameCount);
                    int pBase = f * jointCount * 3;
                    int qBase = f * jointCount * 4;
                    for (int j = 0; j < jointCount; j++)
                    {
                        int p = pBase + 3 * j;
                        if (hasPosition[j])
                        {
                            positions[p] = row[positionColumns[3 * j]];
                            positions[p + 1] = row[positionColumns[3 * j + 1]];
                            positions[p + 2] = row[positionColumns[3 * j + 2]];
                        }
                        else
                        {
                            positions[p] = offsets[3 * j];
                            positions[p + 1] = offsets[3 * j + 1];
                            positions[p + 2] = offsets[3 * j + 2];
                        }

                        QuaternionD q = hasRotation[j]
                            ? Quaternions.FromEuler(
                                row[rotationColumns[3 * j]] * DegreesToRadians,
                                row[rotationColumns[3 * j + 1]] * DegreesToRadians,
                                row[rotationColumns[3 * j + 2]] * DegreesToRadians,
                                orders[j])
                            : QuaternionD.Identity;
                        int qi = qBase + 4 * j;
                        rotations[qi] = q.W;
                        rotations[qi + 1] = q.X;
                        rotations[qi + 2] = q.Y;
                        rotations[qi + 3] = q.Z;
                    }

                    f++;
                }

                if (NextDataLine(out _, out _))
                {
                    throw Error(_lineNumber, $"more motion lines than the {frameCount} that Frames: declares", $"expected exactly {frameCount} motion lines (fix the Frames: count)");
                }

                var motion = new MotionClip(skeleton, frameCount, frameTime, positions, rotations);
                return new BvhAnimation(motion, channelLists, endSites, _source);
            }

            private void ParseRow(int start, int end, double[] row, int frame, int frameCount)
            {
                int count = 0;
                int i = start;
                byte[] d = _data;
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

                        throw Error(_lineNumber, $"frame {frame + 1} of {frameCount} has {total} values", $"expected {row.Length}, one per channel declared in the hierarchy");
                    }

                    if (!TryParseNumberBytes(d, tokenStart, i, out double value))
                    {
                        string token = Encoding.UTF8.GetString(d, tokenStart, i - tokenStart);
                        TryParseNumberText(token, out _, out string? problem);
                        throw Error(_lineNumber, $"frame {frame + 1}, value {count + 1}: {problem}", "expected a finite decimal number such as -12.5 or 1.2e-3");
                    }

                    row[count++] = value;
                }

                if (count != row.Length)
                {
                    throw Error(_lineNumber, $"frame {frame + 1} of {frameCount} has {count} values", $"expected {row.Length}, one per channel declared in the hierarchy");
                }
            }

            /// <summary>Exact fast path for the decimals exporters write; falls back to the framework parser otherwise.</summary>
            private static bool TryParseNumberBytes(byte[] d, int start, int end, out double value)
            {
                int i = start;
                bool negative = false;
                if (d[i] == (byte)'-') { negative = true; i++; }
                else if (d[i] == (byte)'+') { i++; }

                ulong mantissa = 0;
                int digits = 0;        // significant digits accumulated into mantissa
                int exponent = 0;      // decimal exponent applied to mantissa
                bool anyDigit = false;
                bool overflowDigits = false;
                // Integer digits, then (after a '.') fraction digits, by one loop: the first 19
                // significant digits go into the mantissa and each kept fraction digit moves the point
                // one place left; past 19, an integer digit still scales by ten and a fraction digit is
                // dropped.
                bool fraction = false;
                while (true)
                {
                    while (i < end && (uint)(d[i] - '0') <= 9)
                    {
                        anyDigit = true;
                        if (digits < 19)
                        {
                            if (mantissa != 0 || d[i] != (byte)'0')
                            {
                                mantissa = mantissa * 10 + (ulong)(d[i] - '0');
                                digits++;
                            }

                            if (fraction) exponent--;
                        }
                        else
                        {
                            if (!fraction) exponent++;
                            overflowDigits = true;
                        }

                        i++;
                    }

                    if (fraction || i >= end || d[i] != (byte)'.') break;
                    fraction = true;
                    i++;
                }

                if (!anyDigit)
                {
                    value = 0;
                    return false;
                }

                if (i < end && (d[i] == (byte)'e' || d[i] == (byte)'E'))
                {
                    i++;
                    bool expNegative = false;
                    if (i < end && (d[i] == (byte)'-' || d[i] == (byte)'+'))
                    {
                        expNegative = d[i] == (byte)'-';
                        i++;
                    }

                    if (i >= end || (uint)(d[i] - '0') > 9)
                    {
                        value = 0;
                        return false;
                    }

                    int e = 0;
                    while (i < end && (uint)(d[i] - '0') <= 9)
                    {
                        if (e < 100000) e = e * 10 + (d[i] - '0');
                        i++;
                    }

                    exponent += expNegative ? -e : e;
                }

                if (i != end)
                {
                    value = 0;
                    return false;
                }

                if (mantissa == 0)
                {
                    value = negative ? -0.0 : 0.0;
                    return true;
                }

                // Clinger's fast path: mantissa and 10^|e| are both exact doubles, so one IEEE
                // multiplication or division is correctly rounded — the same result double.Parse gives.
                if (!overflowDigits && mantissa <= (1UL << 53) && exponent >= -22 && exponent <= 22)
                {
                    double m = mantissa;
                    value = exponent < 0 ? m / PowersOfTen[-exponent] : m * PowersOfTen[exponent];
                    if (negative) value = -value;
                    return true;
                }

                Span<char> chars = stackalloc char[Math.Min(end - start, 512)];
                if (end - start > 512)
                {
                    value = 0;
                    return false;
                }

                for (int k = 0; k < end - start; k++) chars[k] = (char)d[start + k];
                if (!double.TryParse(chars, NumberStyles.Float, CultureInfo.InvariantCulture, out value))
                {
                    return false;
                }

                return !double.IsInfinity(value) && !double.IsNaN(value);
            }

            /// <summary>Parses a hierarchy number, explaining what is wrong when it is not a finite decimal.</summary>
            private static bool TryParseNumberText(string token, out double value, out string? problem)
            {
                string lower = token.ToLowerInvariant().TrimStart('+', '-');
                if (lower == "nan" || lower == "inf" || lower == "infinity" || lower == "∞")
                {
                    value = 0;
                    problem = $"'{Shorten(token)}' is not a finite number";
                    return false;
                }

                byte[] bytes = Encoding.UTF8.GetBytes(token);
                if (bytes.Length > 0 && TryParseNumberBytes(bytes, 0, bytes.Length, out value))
                {
                    problem = null;
                    return true;
                }

                value = 0;
                bool looksNumeric = double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out double parsed);
                problem = looksNumeric && (double.IsInfinity(parsed) || double.IsNaN(parsed))
                    ? $"'{Shorten(token)}' is not a finite number (out of range)"
                    : $"'{Shorten(token)}' is not a number";
                return false;
            }

            private string RestOfLineAsName(string keyword)
            {
                int line = _tokenLine;
                var parts = new List<string>();
                while (TryPeekToken(out string token) && _tokenLine == line && token != "{")
                {
                    parts.Add(token);
                    NextToken();
                }

                if (parts.Count == 0)
                {
                    throw Error(line, $"{keyword} without a name", $"expected '{keyword} name'");
                }

                return string.Join(" ", parts);
            }

            private void RequireEndOfLine(string expected)
            {
                if (_tokenIndex < _tokens.Count)
                {
                    throw Error(_tokenLine, $"found '{Shorten(_tokens[_tokenIndex])}'", expected);
                }
            }

            private string ExpectToken(string expected)
            {
                if (!TryNextToken(out string token))
                {
                    throw Error(Math.Max(_lineNumber, 1), "the file ends too early (truncated file?)", expected);
                }

                return token;
            }

            private bool TryNextToken(out string token)
            {
                if (!TryPeekToken(out token)) return false;
                _tokenIndex++;
                return true;
            }

            private void NextToken() => _tokenIndex++;

            private bool TryPeekToken(out string token)
            {
                while (_tokenIndex >= _tokens.Count)
                {
                    if (!NextTextLine()) { token = ""; return false; }
                }

                token = _tokens[_tokenIndex];
                return true;
            }

            /// <summary>Reads the next line into the token list (hierarchy and header only).</summary>
            private bool NextTextLine()
            {
                if (!NextLine(out int start, out int end)) return false;
                _tokens.Clear();
                _tokenIndex = 0;
                _tokenLine = _lineNumber;
                int i = start;
                while (i < end)
                {
                    while (i < end && IsSpace(_data[i])) i++;
                    if (i >= end) break;
                    int s = i;
                    while (i < end && !IsSpace(_data[i])) i++;
                    _tokens.Add(Encoding.UTF8.GetString(_data, s, i - s));
                }

                return true;
            }

            /// <summary>The next line that is not blank, in the motion section.</summary>
            private bool NextDataLine(out int start, out int end)
            {
                while (NextLine(out start, out end))
                {
                    for (int i = start; i < end; i++)
                    {
                        if (!IsSpace(_data[i])) return true;
                    }
                }

                return false;
            }

            private bool NextLine(out int start, out int end)
            {
                if (_pos >= _data.Length)
                {
                    start = end = _pos;
                    return false;
                }

                start = _pos;
                int newline = Array.IndexOf(_data, (byte)'\n', _pos);
                if (newline < 0)
                {
                    end = _data.Length;
                    _pos = _data.Length;
                }
                else
                {
                    end = newline;
                    _pos = newline + 1;
                }

                if (end > start && _data[end - 1] == (byte)'\r') end--;
                _lineNumber++;
                return true;
            }

            private static bool IsSpace(byte b) => b == (byte)' ' || b == (byte)'\t' || b == (byte)'\r' || b == (byte)'\f' || b == (byte)'\v';

            private static string Shorten(string token) => token.Length <= 40 ? token : token.Substring(0, 37) + "...";

            private BvhFormatException Error(int line, string problem, string expected) => new BvhFormatException(_source, line, problem, expected);
        }
    }
}
