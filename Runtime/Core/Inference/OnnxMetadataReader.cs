using System;
using System.Collections.Generic;
using System.IO;
using System.Text;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Reads the <c>metadata_props</c> of an ONNX file from its bytes, without an inference engine: the
    /// model contract then comes from the file itself on every backend (a Unity <c>Model</c> keeps no
    /// metadata once imported). A minimal protobuf reader for exactly one thing: <c>ModelProto</c> field 14,
    /// repeated <c>StringStringEntryProto</c> (<c>key</c> = 1, <c>value</c> = 2); every other field is
    /// skipped by its wire type, so the graph (field 7, most of the file) is never parsed.
    /// </summary>
    /// <remarks>
    /// Every length is checked against the bytes left, varints are at most 10 bytes, groups are skipped
    /// with a depth counter (no recursion), and strings must be valid UTF-8; anything else is refused
    /// with a <see cref="ModelContractException"/> (<c>FILE: what; expected</c>).
    /// </remarks>
    public static class OnnxMetadataReader
    {
        private const int MetadataPropsField = 14;
        private const int GraphField = 7;
        private const int GraphNodeField = 1;
        private const int NodeOpTypeField = 4;
        private const int NodeDomainField = 7;
        private const int WireVarint = 0;
        private const int WireFixed64 = 1;
        private const int WireLengthDelimited = 2;
        private const int WireStartGroup = 3;
        private const int WireEndGroup = 4;
        private const int WireFixed32 = 5;

        private static readonly UTF8Encoding StrictUtf8 = new UTF8Encoding(false, true);

        /// <summary>Reads the metadata of the ONNX file at <paramref name="path"/>.</summary>
        /// <exception cref="ModelContractException">The file is missing or is not a well-formed ONNX model.</exception>
        public static IReadOnlyDictionary<string, string> Read(string path)
        {
            if (!File.Exists(path))
            {
                throw new ModelContractException(path, "the model file does not exist", "expected the path of an .onnx file exported by `python3 -m deltainterp export`");
            }

            return Read(File.ReadAllBytes(path), path);
        }

        /// <summary>
        /// Reads the metadata of an ONNX model held in <paramref name="model"/>. A key given twice keeps its
        /// last value (what ONNX Runtime reports).
        /// </summary>
        /// <param name="model">The whole <c>.onnx</c> file.</param>
        /// <param name="source">The file's path or name, for messages.</param>
        /// <exception cref="ModelContractException">The bytes are not a well-formed ONNX model.</exception>
        public static IReadOnlyDictionary<string, string> Read(ReadOnlySpan<byte> model, string source)
        {
            source ??= "<model>";
            var metadata = new Dictionary<string, string>(StringComparer.Ordinal);
            var reader = new WireReader(model, source);
            bool graph = false;
            while (!reader.AtEnd)
            {
                (int field, int wire) = reader.Tag();
                if (field == MetadataPropsField && wire == WireLengthDelimited)
                {
                    ReadEntry(reader.Bytes(), source, metadata);
                }
                else
                {
                    if (field == GraphField && wire == WireLengthDelimited) graph = true;
                    reader.Skip(field, wire);
                }
            }

            if (!graph)
            {
                throw new ModelContractException(source, "the file holds no ONNX graph", "expected an .onnx file exported by `python3 -m deltainterp export`");
            }

            return metadata;
        }

        /// <summary>
        /// The distinct operators of the model's main graph (<c>ModelProto.graph.node[*]</c>): <c>op_type</c>, or
        /// <c>domain::op_type</c> outside the standard domain (<c>""</c> or <c>ai.onnx</c>), sorted ordinally.
        /// Subgraphs are not entered: only a node's graph attribute holds one, and every operator that takes
        /// one (If, Loop, Scan) lies outside the contract itself (<see cref="ModelOperators"/>).
        /// </summary>
        /// <param name="model">The whole <c>.onnx</c> file.</param>
        /// <param name="source">The file's path or name, for messages.</param>
        /// <exception cref="ModelContractException">The bytes are not a well-formed ONNX model.</exception>
        public static IReadOnlyList<string> ReadOperators(ReadOnlySpan<byte> model, string source)
        {
            source ??= "<model>";
            var operators = new SortedSet<string>(StringComparer.Ordinal);
            var reader = new WireReader(model, source);
            while (!reader.AtEnd)
            {
                (int field, int wire) = reader.Tag();
                // Two graph fields merge (protobuf's rule for a repeated message field): the nodes of both count.
                if (field == GraphField && wire == WireLengthDelimited) ReadGraphOperators(reader.Bytes(), source, operators);
                else reader.Skip(field, wire);
            }

            return new List<string>(operators);
        }

        private static void ReadGraphOperators(ReadOnlySpan<byte> graph, string source, SortedSet<string> into)
        {
            var reader = new WireReader(graph, source);
            while (!reader.AtEnd)
            {
                (int field, int wire) = reader.Tag();
                if (field != GraphNodeField || wire != WireLengthDelimited)
                {
                    reader.Skip(field, wire);
                    continue;
                }

                var node = new WireReader(reader.Bytes(), source);
                string opType = "", domain = "";
                while (!node.AtEnd)
                {
                    (int f, int w) = node.Tag();
                    if (f == NodeOpTypeField && w == WireLengthDelimited) opType = node.String();
                    else if (f == NodeDomainField && w == WireLengthDelimited) domain = node.String();
                    else node.Skip(f, w);
                }

                into.Add(domain.Length == 0 || domain == "ai.onnx" ? opType : domain + "::" + opType);
            }
        }

        private static void ReadEntry(ReadOnlySpan<byte> entry, string source, Dictionary<string, string> metadata)
        {
            var reader = new WireReader(entry, source);
            string key = "";
            string value = "";
            while (!reader.AtEnd)
            {
                (int field, int wire) = reader.Tag();
                if ((field == 1 || field == 2) && wire == WireLengthDelimited)
                {
                    string text = reader.String();
                    if (field == 1) key = text;
                    else value = text;
                }
                else
                {
                    reader.Skip(field, wire);
                }
            }

            metadata[key] = value;
        }

        /// <summary>Reads protobuf wire format from a span, refusing anything that runs past its end.</summary>
        private ref struct WireReader
        {
            private readonly ReadOnlySpan<byte> _bytes;
            private readonly string _source;
            private int _pos;

            public WireReader(ReadOnlySpan<byte> bytes, string source)
            {
                _bytes = bytes;
                _source = source;
                _pos = 0;
            }

            public bool AtEnd => _pos >= _bytes.Length;

            public (int Field, int Wire) Tag()
            {
                int at = _pos;
                ulong tag = Varint();
                ulong field = tag >> 3;
                if (field == 0 || field > 536870911)
                {
                    throw Malformed($"field number {field} at byte {at}", "field numbers from 1 to 2^29 − 1");
                }

                return ((int)field, (int)(tag & 7));
            }

            public ulong Varint()
            {
                ulong value = 0;
                for (int shift = 0; shift < 70; shift += 7)
                {
                    if (_pos >= _bytes.Length) throw Malformed($"the data ends inside a varint at byte {_pos}", "the rest of the file (it looks truncated)");
                    byte b = _bytes[_pos++];
                    value |= (ulong)(b & 0x7F) << shift;
                    if ((b & 0x80) == 0) return value;
                }

                throw Malformed($"a varint longer than 10 bytes ends at byte {_pos}", "protobuf varints of at most 10 bytes");
            }

            public ReadOnlySpan<byte> Bytes()
            {
                int at = _pos;
                ulong length = Varint();
                if (length > (ulong)(_bytes.Length - _pos))
                {
                    throw Malformed($"a field at byte {at} claims {length} bytes but {_bytes.Length - _pos} remain", "the rest of the file (it looks truncated or is not ONNX)");
                }

                ReadOnlySpan<byte> slice = _bytes.Slice(_pos, (int)length);
                _pos += (int)length;
                return slice;
            }

            public string String()
            {
                int at = _pos;
                ReadOnlySpan<byte> raw = Bytes();
                try
                {
                    return StrictUtf8.GetString(raw.ToArray());
                }
                catch (ArgumentException)
                {
                    throw Malformed($"the string at byte {at} is not valid UTF-8", "UTF-8 text, as ONNX stores strings");
                }
            }

            public void Skip(int field, int wire)
            {
                switch (wire)
                {
                    case WireVarint: Varint(); break;
                    case WireFixed64: Advance(8); break;
                    case WireLengthDelimited: Bytes(); break;
                    case WireFixed32: Advance(4); break;
                    case WireStartGroup: SkipGroup(field); break;
                    default:
                        throw Malformed($"wire type {wire} (field {field}) before byte {_pos}", "wire types 0 to 5 of the protobuf encoding");
                }
            }

            private void SkipGroup(int field)
            {
                // Deprecated groups nest; a depth counter skips them without recursion.
                var open = new Stack<int>();
                open.Push(field);
                while (open.Count > 0)
                {
                    if (AtEnd) throw Malformed($"group {open.Peek()} is never closed", "an end-group tag for every start-group tag");
                    (int f, int w) = Tag();
                    if (w == WireStartGroup)
                    {
                        open.Push(f);
                    }
                    else if (w == WireEndGroup)
                    {
                        int expected = open.Pop();
                        if (f != expected) throw Malformed($"group {expected} is closed as {f}", "matching start- and end-group field numbers");
                    }
                    else
                    {
                        Skip(f, w);
                    }
                }
            }

            private void Advance(int count)
            {
                if (_bytes.Length - _pos < count) throw Malformed($"the data ends inside a {count}-byte field at byte {_pos}", "the rest of the file (it looks truncated)");
                _pos += count;
            }

            private ModelContractException Malformed(string what, string expected) =>
                new ModelContractException(_source, "not a well-formed ONNX file: " + what, "expected " + expected);
        }
    }
}
