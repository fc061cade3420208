using System.Globalization;
using System.Text;

namespace DeltaInterpolator.Cli
{
    /// <summary>
    /// Makes text that came from a file (joint names, paths, parser messages quoting the file) safe to
    /// print: control characters (C0, DEL, C1 — ESC among them, which would let a file clear the screen
    /// or rewrite the terminal's title), Unicode bidirectional overrides and line/paragraph separators
    /// are shown as escapes (<c>\x1b</c>, <c>\u202e</c>), and text longer than a limit keeps its start
    /// and end with the middle replaced by a count of what was left out.
    /// </summary>
    public static class TerminalText
    {
        /// <summary>A limit for names shown in tables and messages.</summary>
        public const int NameLength = 80;

        /// <summary>A limit for a whole message line.</summary>
        public const int LineLength = 2000;

        /// <summary>
        /// <paramref name="text"/> with control characters escaped and, when longer than
        /// <paramref name="maxLength"/> characters, clipped in the middle (start and end kept).
        /// </summary>
        public static string Safe(string? text, int maxLength)
        {
            if (string.IsNullOrEmpty(text)) return text ?? "";
            if (maxLength < 16) maxLength = 16;

            // Clip first (on the raw text) so that a 10 MB name costs a few kilobytes of work to print.
            string body = text!;
            if (body.Length > maxLength)
            {
                int head = maxLength * 2 / 3;
                int tail = maxLength - head;
                // Never split a surrogate pair.
                if (char.IsHighSurrogate(body[head - 1])) head--;
                if (char.IsLowSurrogate(body[body.Length - tail])) tail--;
                string omitted = $"…[{(body.Length - head - tail).ToString("N0", CultureInfo.InvariantCulture)} characters]…";
                return Escape(body.Substring(0, head)) + omitted + Escape(body.Substring(body.Length - tail));
            }

            return Escape(body);
        }

        /// <summary>True for a character that must not reach a terminal raw.</summary>
        public static bool IsUnsafe(char c)
        {
            return c < 0x20 || c == 0x7f || (c >= 0x80 && c <= 0x9f)
                || (c >= '\u202a' && c <= '\u202e') || (c >= '\u2066' && c <= '\u2069')
                || c == '\u2028' || c == '\u2029' || c == '\u200e' || c == '\u200f';
        }

        private static string Escape(string text)
        {
            int first = -1;
            for (int i = 0; i < text.Length; i++)
            {
                if (IsUnsafe(text[i]))
                {
                    first = i;
                    break;
                }
            }

            if (first < 0) return text;
            var sb = new StringBuilder(text.Length + 16);
            sb.Append(text, 0, first);
            for (int i = first; i < text.Length; i++)
            {
                char c = text[i];
                if (!IsUnsafe(c))
                {
                    sb.Append(c);
                }
                else if (c == '\t')
                {
                    sb.Append("\\t");
                }
                else if (c == '\n')
                {
                    sb.Append("\\n");
                }
                else if (c == '\r')
                {
                    sb.Append("\\r");
                }
                else if (c <= 0xff)
                {
                    sb.Append("\\x").Append(((int)c).ToString("x2", CultureInfo.InvariantCulture));
                }
                else
                {
                    sb.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                }
            }

            return sb.ToString();
        }
    }
}
