using System;
using System.Globalization;
using System.Text;

namespace DeltaInterpolator.Core.Bvh
{
    /// <summary>
    /// The numbers of a BVH file: finite decimals such as <c>-12.5</c>, <c>1.2e-3</c>, <c>.5</c>, parsed
    /// straight from the bytes with an exact fast path for short decimals (the form every exporter writes;
    /// the same double that <c>double.Parse</c> gives) and the framework parser otherwise. NaN, infinities
    /// and values beyond the double range are refused, with a phrase saying why.
    /// </summary>
    internal static class BvhNumberParser
    {
        private static readonly double[] PowersOfTen =
        {
            1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
            1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
        };

        /// <summary>Exact fast path for the decimals exporters write; falls back to the framework parser otherwise.</summary>
        public static bool TryParse(byte[] d, int start, int end, out double value)
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
        public static bool TryParseText(string token, out double value, out string? problem)
        {
            string lower = token.ToLowerInvariant().TrimStart('+', '-');
            if (lower == "nan" || lower == "inf" || lower == "infinity" || lower == "∞")
            {
                value = 0;
                problem = $"'{BvhTokenizer.Shorten(token)}' is not a finite number";
                return false;
            }

            byte[] bytes = Encoding.UTF8.GetBytes(token);
            if (bytes.Length > 0 && TryParse(bytes, 0, bytes.Length, out value))
            {
                problem = null;
                return true;
            }

            value = 0;
            bool looksNumeric = double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out double parsed);
            problem = looksNumeric && (double.IsInfinity(parsed) || double.IsNaN(parsed))
                ? $"'{BvhTokenizer.Shorten(token)}' is not a finite number (out of range)"
                : $"'{BvhTokenizer.Shorten(token)}' is not a number";
            return false;
        }
    }
}
