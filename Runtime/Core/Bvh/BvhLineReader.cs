using System;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// Walks the lines of BVH bytes without copying them: each call gives the next line's byte range and
    /// counts line numbers for error messages. Lines end with LF, CRLF or a lone CR (classic Mac files),
    /// so every convention numbers lines the way an editor shows them. A UTF-8 byte order mark is skipped.
    /// </summary>
    internal sealed class BvhLineReader
    {
        private readonly byte[] _data;
        private int _position;

        /// <summary>Starts at the first line of <paramref name="data"/>.</summary>
        public BvhLineReader(byte[] data)
        {
            _data = data;
            // A UTF-8 byte order mark is not part of the text.
            if (data.Length >= 3 && data[0] == 0xEF && data[1] == 0xBB && data[2] == 0xBF) _position = 3;
        }

        /// <summary>The bytes being read.</summary>
        public byte[] Data => _data;

        /// <summary>1-based number of the line last returned (0 before the first).</summary>
        public int LineNumber { get; private set; }

        /// <summary>Bytes not yet returned as lines.</summary>
        public int RemainingBytes => _data.Length - _position;

        /// <summary>The next line as [start, end) without its line break; false at the end of the data.</summary>
        public bool NextLine(out int start, out int end)
        {
            if (_position >= _data.Length)
            {
                start = end = _position;
                return false;
            }

            start = _position;
            int found = _data.AsSpan(_position).IndexOfAny((byte)'\n', (byte)'\r');
            if (found < 0)
            {
                end = _data.Length;
                _position = _data.Length;
            }
            else
            {
                end = _position + found;
                _position = end + 1;
                if (_data[end] == (byte)'\r' && _position < _data.Length && _data[_position] == (byte)'\n') _position++;
            }

            LineNumber++;
            return true;
        }

        /// <summary>The next line that is not blank (motion section).</summary>
        public bool NextDataLine(out int start, out int end)
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

        /// <summary>Blanks between tokens: space, tab, form feed, vertical tab (and CR, for robustness).</summary>
        public static bool IsSpace(byte b) => b == (byte)' ' || b == (byte)'\t' || b == (byte)'\r' || b == (byte)'\f' || b == (byte)'\v';
    }
}
