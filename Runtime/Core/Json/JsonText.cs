using System.Globalization;
using System.Text;

namespace DeltaInterpolator.Core.Json
{
    /// <summary>
    /// The writing side of <see cref="JsonValue"/>: the one way Core writes a JSON string, so that the model
    /// contract's JSON and the model metadata escape the same characters and read back identically.
    /// </summary>
    public static class JsonText
    {
        /// <summary>Appends <paramref name="value"/> as a quoted JSON string (control characters escaped).</summary>
        public static StringBuilder AppendString(StringBuilder text, string value)
        {
            text.Append('"');
            foreach (char c in value)
            {
                switch (c)
                {
                    case '"': text.Append("\\\""); break;
                    case '\\': text.Append("\\\\"); break;
                    case '\n': text.Append("\\n"); break;
                    case '\r': text.Append("\\r"); break;
                    case '\t': text.Append("\\t"); break;
                    default:
                        if (c < 0x20) text.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                        else text.Append(c);
                        break;
                }
            }

            return text.Append('"');
        }

        /// <summary><paramref name="value"/> as a quoted JSON string.</summary>
        public static string Quote(string value) => AppendString(new StringBuilder(value.Length + 2), value).ToString();
    }
}
