using System;
using System.Collections.Generic;
using System.Text;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// The words of the hierarchy and the MOTION header, one line at a time: peek and take the next word
    /// and know which line it is on (the grammar needs line boundaries: a CHANNELS or OFFSET line ends its
    /// list, a joint's name is the rest of its line). The motion lines are read by bytes instead
    /// (<see cref="BvhLineReader"/>), without a string per value.
    /// </summary>
    internal sealed class BvhTokenizer
    {
        private readonly BvhLineReader _lines;
        private readonly List<string> _tokens = new List<string>();
        private int _index;

        /// <summary>Reads words from <paramref name="lines"/>.</summary>
        public BvhTokenizer(BvhLineReader lines)
        {
            _lines = lines;
        }

        /// <summary>The lines underneath, positioned after the line of the last word read.</summary>
        public BvhLineReader Lines => _lines;

        /// <summary>The line of the word last peeked or taken.</summary>
        public int TokenLine { get; private set; }

        /// <summary>The line last read (for "the file ends" messages).</summary>
        public int LineNumber => _lines.LineNumber;

        /// <summary>True when words remain on the current line (after the last one taken).</summary>
        public bool HasMoreOnLine => _index < _tokens.Count;

        /// <summary>The next word on the current line, when <see cref="HasMoreOnLine"/>.</summary>
        public string RestOfLineFirst => _tokens[_index];

        /// <summary>The next word without taking it; false at the end of the data.</summary>
        public bool TryPeek(out string token)
        {
            while (_index >= _tokens.Count)
            {
                if (!NextTextLine())
                {
                    token = "";
                    return false;
                }
            }

            token = _tokens[_index];
            return true;
        }

        /// <summary>Takes the next word; false at the end of the data.</summary>
        public bool TryNext(out string token)
        {
            if (!TryPeek(out token)) return false;
            _index++;
            return true;
        }

        /// <summary>
        /// Takes the next word; at the end of the data, the error of a truncated <paramref name="source"/> that says what
        /// was <paramref name="expected"/> there (the hierarchy's and the MOTION header's one end-of-file message).
        /// </summary>
        public string Next(string source, string expected)
        {
            if (!TryNext(out string token))
            {
                throw new BvhFormatException(source, Math.Max(LineNumber, 1), "the file ends too early (truncated file?)", expected);
            }

            return token;
        }

        /// <summary>Takes the word last peeked.</summary>
        public void Skip() => _index++;

        /// <summary>
        /// A word or name as error messages show it: at most 40 characters, so a file with a huge name
        /// cannot make a huge message.
        /// </summary>
        public static string Shorten(string token) => token.Length <= 40 ? token : token.Substring(0, 37) + "...";

        /// <summary>Reads the next line into the word list.</summary>
        private bool NextTextLine()
        {
            if (!_lines.NextLine(out int start, out int end)) return false;
            byte[] data = _lines.Data;
            _tokens.Clear();
            _index = 0;
            TokenLine = _lines.LineNumber;
            int i = start;
            while (i < end)
            {
                while (i < end && BvhLineReader.IsSpace(data[i])) i++;
                if (i >= end) break;
                int s = i;
                while (i < end && !BvhLineReader.IsSpace(data[i])) i++;
                _tokens.Add(Encoding.UTF8.GetString(data, s, i - s));
            }

            return true;
        }
    }
}
