using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace DeltaInterpolator.Core.Json
{
    /// <summary>The kind of a <see cref="JsonValue"/>.</summary>
    public enum JsonKind
    {
        /// <summary>null</summary>
        Null,
        /// <summary>true or false</summary>
        Boolean,
        /// <summary>a number</summary>
        Number,
        /// <summary>a string</summary>
        String,
        /// <summary>an array</summary>
        Array,
        /// <summary>an object</summary>
        Object,
    }

    /// <summary>
    /// A small, strict JSON reader for the project's own files (statistics, model metadata) that Core
    /// must read without engine or framework dependencies (netstandard2.1 has no System.Text.Json in
    /// Unity). Every value remembers its source and line so that a wrong shape is reported as
    /// <c>FILE:LINE: what was wrong; what was expected</c> (<see cref="DataFormatException"/>).
    /// </summary>
    public sealed class JsonValue
    {
        private readonly object? _value;

        private JsonValue(JsonKind kind, object? value, string source, int line)
        {
            Kind = kind;
            _value = value;
            Source = source;
            Line = line;
        }

        /// <summary>The kind of value.</summary>
        public JsonKind Kind { get; }

        /// <summary>The file or name the value was read from.</summary>
        public string Source { get; }

        /// <summary>1-based line where the value starts.</summary>
        public int Line { get; }

        /// <summary>Parses one JSON document.</summary>
        /// <exception cref="DataFormatException">The text is not valid JSON.</exception>
        public static JsonValue Parse(string text, string source)
        {
            var reader = new Reader(text ?? throw new ArgumentNullException(nameof(text)), source ?? "<json>");
            return reader.ParseDocument();
        }

        /// <summary>The number; throws naming <paramref name="what"/> when this is not a finite number.</summary>
        public double ExpectNumber(string what)
        {
            if (Kind != JsonKind.Number) throw Mismatch(what, "a number");
            return (double)_value!;
        }

        /// <summary>The string; throws naming <paramref name="what"/> when this is not a string.</summary>
        public string ExpectString(string what)
        {
            if (Kind != JsonKind.String) throw Mismatch(what, "a string");
            return (string)_value!;
        }

        /// <summary>The elements; throws naming <paramref name="what"/> when this is not an array.</summary>
        public IReadOnlyList<JsonValue> ExpectArray(string what)
        {
            if (Kind != JsonKind.Array) throw Mismatch(what, "an array");
            return (List<JsonValue>)_value!;
        }

        /// <summary>The members; throws naming <paramref name="what"/> when this is not an object.</summary>
        public IReadOnlyDictionary<string, JsonValue> ExpectObject(string what)
        {
            if (Kind != JsonKind.Object) throw Mismatch(what, "an object");
            return (Dictionary<string, JsonValue>)_value!;
        }

        /// <summary>The member <paramref name="key"/> of this object; throws when absent.</summary>
        public JsonValue ExpectMember(string key)
        {
            IReadOnlyDictionary<string, JsonValue> members = ExpectObject("the document");
            if (!members.TryGetValue(key, out JsonValue? value))
            {
                throw new DataFormatException(Source, Line, $"the object has no \"{key}\" member", $"expected a \"{key}\" member");
            }

            return value;
        }

        /// <summary>An array of exactly <paramref name="count"/> numbers (any count when negative).</summary>
        public double[] ExpectNumbers(string what, int count)
        {
            IReadOnlyList<JsonValue> items = ExpectArray(what);
            if (count >= 0 && items.Count != count)
            {
                throw new DataFormatException(Source, Line, $"{what} has {items.Count} values", $"expected {count}");
            }

            var result = new double[items.Count];
            for (int i = 0; i < result.Length; i++) result[i] = items[i].ExpectNumber($"{what}[{i}]");
            return result;
        }

        private DataFormatException Mismatch(string what, string expected)
        {
            return new DataFormatException(Source, Line, $"{what} is {Describe(Kind)}", "expected " + expected);
        }

        private static string Describe(JsonKind kind)
        {
            switch (kind)
            {
                case JsonKind.Null: return "null";
                case JsonKind.Boolean: return "a boolean";
                case JsonKind.Number: return "a number";
                case JsonKind.String: return "a string";
                case JsonKind.Array: return "an array";
                default: return "an object";
            }
        }

        private sealed class Reader
        {
            private readonly string _text;
            private readonly string _source;
            private int _pos;
            private int _line = 1;

            public Reader(string text, string source)
            {
                _text = text;
                _source = source;
                if (_text.Length > 0 && _text[0] == '\uFEFF') _pos = 1;
            }

            public JsonValue ParseDocument()
            {
                SkipWhitespace();
                if (_pos >= _text.Length) throw Error("the file is empty", "expected a JSON value");
                JsonValue value = ParseValue(0);
                SkipWhitespace();
                if (_pos < _text.Length) throw Error($"unexpected '{_text[_pos]}' after the JSON value", "expected the end of the file");
                return value;
            }

            private JsonValue ParseValue(int depth)
            {
                if (depth > 256) throw Error("nesting deeper than 256 levels", "expected a flatter document");
                SkipWhitespace();
                if (_pos >= _text.Length) throw Error("the file ends too early (truncated?)", "expected a JSON value");
                int line = _line;
                char c = _text[_pos];
                switch (c)
                {
                    case '{': return ParseObject(depth, line);
                    case '[': return ParseArray(depth, line);
                    case '"': return new JsonValue(JsonKind.String, ParseString(), _source, line);
                    case 't': Literal("true"); return new JsonValue(JsonKind.Boolean, true, _source, line);
                    case 'f': Literal("false"); return new JsonValue(JsonKind.Boolean, false, _source, line);
                    case 'n': Literal("null"); return new JsonValue(JsonKind.Null, null, _source, line);
                    default:
                        if (c == '-' || (c >= '0' && c <= '9')) return new JsonValue(JsonKind.Number, ParseNumber(), _source, line);
                        throw Error($"unexpected '{c}'", "expected a JSON value (object, array, string, number, true, false or null)");
                }
            }

            private JsonValue ParseObject(int depth, int line)
            {
                _pos++;
                var members = new Dictionary<string, JsonValue>(StringComparer.Ordinal);
                SkipWhitespace();
                if (Peek() == '}') { _pos++; return new JsonValue(JsonKind.Object, members, _source, line); }
                while (true)
                {
                    SkipWhitespace();
                    if (Peek() != '"') throw Error(DescribeHere(), "expected a member name in double quotes");
                    string key = ParseString();
                    SkipWhitespace();
                    if (Peek() != ':') throw Error(DescribeHere(), $"expected ':' after \"{key}\"");
                    _pos++;
                    JsonValue value = ParseValue(depth + 1);
                    if (members.ContainsKey(key)) throw Error($"member \"{key}\" appears twice", "expected unique member names");
                    members.Add(key, value);
                    SkipWhitespace();
                    char c = Peek();
                    if (c == ',') { _pos++; continue; }
                    if (c == '}') { _pos++; return new JsonValue(JsonKind.Object, members, _source, line); }
                    throw Error(DescribeHere(), "expected ',' or '}' in the object");
                }
            }

            private JsonValue ParseArray(int depth, int line)
            {
                _pos++;
                var items = new List<JsonValue>();
                SkipWhitespace();
                if (Peek() == ']') { _pos++; return new JsonValue(JsonKind.Array, items, _source, line); }
                while (true)
                {
                    items.Add(ParseValue(depth + 1));
                    SkipWhitespace();
                    char c = Peek();
                    if (c == ',') { _pos++; continue; }
                    if (c == ']') { _pos++; return new JsonValue(JsonKind.Array, items, _source, line); }
                    throw Error(DescribeHere(), "expected ',' or ']' in the array");
                }
            }

            private string ParseString()
            {
                _pos++;
                var sb = new StringBuilder();
                while (true)
                {
                    if (_pos >= _text.Length) throw Error("the file ends inside a string", "expected a closing '\"'");
                    char c = _text[_pos++];
                    if (c == '"') return sb.ToString();
                    if (c == '\n') throw Error("a line break inside a string", "expected a closing '\"' on the same line");
                    if (c != '\\') { sb.Append(c); continue; }
                    if (_pos >= _text.Length) throw Error("the file ends inside a string", "expected an escape sequence");
                    char e = _text[_pos++];
                    switch (e)
                    {
                        case '"': sb.Append('"'); break;
                        case '\\': sb.Append('\\'); break;
                        case '/': sb.Append('/'); break;
                        case 'b': sb.Append('\b'); break;
                        case 'f': sb.Append('\f'); break;
                        case 'n': sb.Append('\n'); break;
                        case 'r': sb.Append('\r'); break;
                        case 't': sb.Append('\t'); break;
                        case 'u':
                            if (_pos + 4 > _text.Length || !int.TryParse(_text.Substring(_pos, 4), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out int code))
                            {
                                throw Error("a bad \\u escape", "expected four hexadecimal digits");
                            }

                            sb.Append((char)code);
                            _pos += 4;
                            break;
                        default: throw Error($"unknown escape '\\{e}'", "expected one of \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX");
                    }
                }
            }

            private double ParseNumber()
            {
                int start = _pos;
                while (_pos < _text.Length && "+-0123456789.eE".IndexOf(_text[_pos]) >= 0) _pos++;
                string token = _text.Substring(start, _pos - start);
                if (!double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) || double.IsNaN(value) || double.IsInfinity(value))
                {
                    throw Error($"'{token}' is not a finite number", "expected a JSON number");
                }

                return value;
            }

            private void Literal(string word)
            {
                if (string.CompareOrdinal(_text, _pos, word, 0, word.Length) != 0)
                {
                    throw Error(DescribeHere(), "expected a JSON value (NaN and Infinity are not JSON)");
                }

                _pos += word.Length;
            }

            private void SkipWhitespace()
            {
                while (_pos < _text.Length)
                {
                    char c = _text[_pos];
                    if (c == '\n') _line++;
                    else if (c != ' ' && c != '\t' && c != '\r') break;
                    _pos++;
                }
            }

            private char Peek() => _pos < _text.Length ? _text[_pos] : '\0';

            private string DescribeHere() => _pos < _text.Length ? $"unexpected '{_text[_pos]}'" : "the file ends too early (truncated?)";

            private DataFormatException Error(string problem, string expected) => new DataFormatException(_source, _line, problem, expected);
        }
    }
}
