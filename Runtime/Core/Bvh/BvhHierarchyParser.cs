using System;
using System.Collections.Generic;
using System.Globalization;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// The grammar of the HIERARCHY section, from <c>HIERARCHY</c> through the <c>MOTION</c> keyword:
    /// joints with their OFFSET, CHANNELS, children and End Sites, in file order. Nesting is followed with
    /// an explicit stack of open joints, not by recursion, so any depth the memory holds parses (a file
    /// nested 80,000 joints deep reads like any other) and the call stack never overflows.
    /// </summary>
    internal sealed class BvhHierarchyParser
    {
        private const string ChannelNames = "Xposition, Yposition, Zposition, Xrotation, Yrotation or Zrotation";

        private readonly BvhTokenizer _tokens;
        private readonly string _source;
        private readonly List<BvhJointDefinition> _joints = new List<BvhJointDefinition>();
        private readonly Dictionary<string, int> _jointLines = new Dictionary<string, int>(StringComparer.Ordinal);

        /// <summary>Parses from the start of <paramref name="tokens"/>; <paramref name="source"/> names the file in errors.</summary>
        public BvhHierarchyParser(BvhTokenizer tokens, string source)
        {
            _tokens = tokens;
            _source = source;
        }

        /// <summary>
        /// Reads the hierarchy and the <c>MOTION</c> keyword after it; the tokenizer is left after MOTION.
        /// </summary>
        /// <returns>The joints, parents before children.</returns>
        /// <exception cref="BvhFormatException">The hierarchy is malformed.</exception>
        public List<BvhJointDefinition> Parse()
        {
            if (!_tokens.TryPeek(out string first))
            {
                throw Error(1, "the file is empty", "expected a BVH file starting with HIERARCHY");
            }

            if (first != "HIERARCHY")
            {
                throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(first)}' where the file should start", "expected HIERARCHY (is this a BVH file?)");
            }

            _tokens.Skip();
            string root = _tokens.Next(_source, "expected ROOT and the root joint's name after HIERARCHY");
            if (root != "ROOT")
            {
                throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(root)}' after HIERARCHY", "expected ROOT and the root joint's name");
            }

            ParseJoints(_tokens.TokenLine);

            if (!_tokens.TryPeek(out string afterRoot))
            {
                throw Error(_tokens.LineNumber, "the file ends after the hierarchy", "expected a MOTION section with Frames: and Frame Time:");
            }

            if (afterRoot == "ROOT")
            {
                throw Error(_tokens.TokenLine, "a second ROOT", "expected MOTION after the first skeleton (one skeleton per file)");
            }

            if (afterRoot == "}")
            {
                throw Error(_tokens.TokenLine, "a '}' without a matching '{' (unbalanced braces)", "expected MOTION after the root joint's closing brace");
            }

            if (afterRoot != "MOTION")
            {
                throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(afterRoot)}' after the hierarchy", "expected MOTION");
            }

            _tokens.Skip();
            return _joints;
        }

        /// <summary>The root joint (its ROOT keyword just taken on <paramref name="rootLine"/>) and everything inside it.</summary>
        private void ParseJoints(int rootLine)
        {
            var open = new Stack<int>();
            open.Push(OpenJoint(-1, rootLine));
            while (open.Count > 0)
            {
                int index = open.Peek();
                BvhJointDefinition joint = _joints[index];
                string name = BvhTokenizer.Shorten(joint.Name);
                if (!_tokens.TryNext(out string token))
                {
                    throw Error(_tokens.LineNumber, $"the file ends inside joint '{name}' (unbalanced braces or truncated file)", "expected '}' closing the joint, then MOTION");
                }

                int tokenLine = _tokens.TokenLine;
                switch (token)
                {
                    case "OFFSET":
                        if (joint.HasOffset) throw Error(tokenLine, $"a second OFFSET in joint '{name}'", "expected one OFFSET per joint");
                        joint.Offset = ParseOffset("joint '" + name + "'");
                        joint.HasOffset = true;
                        break;
                    case "CHANNELS":
                        if (joint.Channels != null) throw Error(tokenLine, $"a second CHANNELS line in joint '{name}'", "expected one CHANNELS line per joint");
                        joint.Channels = ParseChannels(name);
                        break;
                    case "JOINT":
                        RequireOffsetAndChannels(joint, tokenLine);
                        open.Push(OpenJoint(index, tokenLine));
                        break;
                    case "End":
                        RequireOffsetAndChannels(joint, tokenLine);
                        ParseEndSite(joint, name);
                        break;
                    case "}":
                        RequireOffsetAndChannels(joint, tokenLine);
                        open.Pop();
                        break;
                    case "MOTION":
                        throw Error(tokenLine, $"MOTION while joint '{name}' is still open (unbalanced braces)", "expected '}' closing every joint before MOTION");
                    case "ROOT":
                        throw Error(tokenLine, $"ROOT inside joint '{name}'", "expected JOINT, End Site or '}'");
                    default:
                        throw Error(tokenLine, $"found '{BvhTokenizer.Shorten(token)}' in joint '{name}'", "expected OFFSET, CHANNELS, JOINT, End Site or '}'");
                }
            }
        }

        /// <summary>Reads a ROOT or JOINT name and its opening brace; returns the new joint's index.</summary>
        private int OpenJoint(int parent, int line)
        {
            string name = RestOfLineAsName(parent < 0 ? "ROOT" : "JOINT");
            if (_jointLines.TryGetValue(name, out int firstLine))
            {
                throw Error(line, $"joint name '{BvhTokenizer.Shorten(name)}' is used twice (first on line {firstLine})", "expected unique joint names");
            }

            _jointLines.Add(name, line);
            int index = _joints.Count;
            _joints.Add(new BvhJointDefinition { Name = name, Parent = parent, Line = line });
            ExpectOpeningBrace("joint '" + BvhTokenizer.Shorten(name) + "'");
            return index;
        }

        private void RequireOffsetAndChannels(BvhJointDefinition joint, int line)
        {
            if (!joint.HasOffset)
            {
                throw Error(line, $"joint '{BvhTokenizer.Shorten(joint.Name)}' has no OFFSET", "expected OFFSET x y z before its children or closing brace");
            }

            if (joint.Channels == null)
            {
                throw Error(line, $"joint '{BvhTokenizer.Shorten(joint.Name)}' has no CHANNELS line", "expected CHANNELS 3 or CHANNELS 6 with the channel names before its children or closing brace");
            }
        }

        private void ParseEndSite(BvhJointDefinition joint, string name)
        {
            string site = _tokens.Next(_source, "expected 'Site' after 'End'");
            if (site != "Site")
            {
                throw Error(_tokens.TokenLine, $"found 'End {BvhTokenizer.Shorten(site)}' in joint '{name}'", "expected 'End Site'");
            }

            ExpectOpeningBrace($"the End Site of joint '{name}'");
            string offset = _tokens.Next(_source, $"expected OFFSET in the End Site of joint '{name}'");
            if (offset != "OFFSET")
            {
                throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(offset)}' in the End Site of joint '{name}'", "expected OFFSET x y z");
            }

            joint.EndSites.Add(ParseOffset($"the End Site of joint '{name}'"));
            string close = _tokens.Next(_source, $"expected '}}' closing the End Site of joint '{name}' (unbalanced braces)");
            if (close != "}")
            {
                throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(close)}' in the End Site of joint '{name}'", "expected '}' closing the End Site (an End Site holds only an OFFSET)");
            }
        }

        private void ExpectOpeningBrace(string what)
        {
            string brace = _tokens.Next(_source, $"expected '{{' opening {what}");
            if (brace != "{")
            {
                throw Error(_tokens.TokenLine, $"found '{BvhTokenizer.Shorten(brace)}' after the name of {what}", "expected '{'");
            }
        }

        private Vector3D ParseOffset(string what)
        {
            int line = _tokens.TokenLine;
            double x = ParseNumberOnLine(line, what);
            double y = ParseNumberOnLine(line, what);
            double z = ParseNumberOnLine(line, what);
            return new Vector3D(x, y, z);
        }

        private double ParseNumberOnLine(int line, string what)
        {
            const string expected = "expected three numbers: OFFSET x y z";
            if (!_tokens.TryPeek(out string token) || _tokens.TokenLine != line)
            {
                throw Error(line, $"the OFFSET of {what} has too few values", expected);
            }

            _tokens.Skip();
            if (!BvhNumberParser.TryParseText(token, out double value, out string? problem))
            {
                throw Error(line, $"the OFFSET of {what}: {problem}", expected);
            }

            return value;
        }

        private BvhChannel[] ParseChannels(string joint)
        {
            int line = _tokens.TokenLine;
            if (!_tokens.TryPeek(out string countText) || _tokens.TokenLine != line)
            {
                throw Error(line, $"CHANNELS of joint '{joint}' has no channel count", "expected CHANNELS 3 or CHANNELS 6 followed by the channel names");
            }

            _tokens.Skip();
            if (!int.TryParse(countText, NumberStyles.None, CultureInfo.InvariantCulture, out int count) || (count != 3 && count != 6))
            {
                throw Error(line, $"CHANNELS {BvhTokenizer.Shorten(countText)} on joint '{joint}'", "expected 3 or 6 channels");
            }

            var channels = new BvhChannel[count];
            for (int i = 0; i < count; i++)
            {
                if (!_tokens.TryPeek(out string name) || _tokens.TokenLine != line)
                {
                    throw Error(line, $"CHANNELS {count} of joint '{joint}' names only {i} channels", $"expected {count} channel names on the CHANNELS line");
                }

                _tokens.Skip();
                if (!BvhChannels.TryParse(name, out channels[i]))
                {
                    throw Error(line, $"unknown channel '{BvhTokenizer.Shorten(name)}' on joint '{joint}'", "expected " + ChannelNames);
                }
            }

            if (_tokens.TryPeek(out string extra) && _tokens.TokenLine == line)
            {
                throw Error(line, $"CHANNELS {count} of joint '{joint}' is followed by '{BvhTokenizer.Shorten(extra)}'", $"expected exactly {count} channel names");
            }

            string? problem = BvhAnimation.DescribeChannelProblem(channels);
            if (problem != null)
            {
                throw Error(line, $"joint '{joint}': {problem}", "expected 3 rotation channels, 3 position channels, or all 6, each once");
            }

            return channels;
        }

        private string RestOfLineAsName(string keyword)
        {
            int line = _tokens.TokenLine;
            var parts = new List<string>();
            while (_tokens.TryPeek(out string token) && _tokens.TokenLine == line && token != "{")
            {
                parts.Add(token);
                _tokens.Skip();
            }

            if (parts.Count == 0)
            {
                throw Error(line, $"{keyword} without a name", $"expected '{keyword} name'");
            }

            string name = string.Join(" ", parts);
            if (string.IsNullOrWhiteSpace(name))
            {
                // E.g. a lone U+00A0 or U+2028: a token to the tokenizer, but no name to a reader (or a skeleton).
                var codes = new List<string>();
                for (int i = 0; i < name.Length && i < 8; i++) codes.Add("U+" + ((int)name[i]).ToString("X4", CultureInfo.InvariantCulture));
                if (name.Length > 8) codes.Add("…");
                throw Error(line, $"{keyword} name is only blank characters ({string.Join(" ", codes)})", "expected a joint name with a visible character");
            }

            return name;
        }

        private BvhFormatException Error(int line, string problem, string expected) => new BvhFormatException(_source, line, problem, expected);
    }
}
